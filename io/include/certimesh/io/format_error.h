// The one error every reader and writer throws: which file, which line, and why.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace certimesh::io {

/// A file that cannot be read or written as the format says. `what()` is "FILE:LINE: why"
/// (or "FILE: why" when no line applies, line == 0); the CLI prefixes "error: ".
class FormatError : public std::runtime_error {
 public:
  FormatError(std::string file, std::size_t line, std::string why)
      : std::runtime_error(compose(file, line, why)),
        file_(std::move(file)), line_(line), why_(std::move(why)) {}

  const std::string& file() const noexcept { return file_; }
  std::size_t line() const noexcept { return line_; }
  const std::string& why() const noexcept { return why_; }

 private:
  static std::string compose(const std::string& file, std::size_t line, const std::string& why) {
    return line == 0 ? file + ": " + why : file + ":" + std::to_string(line) + ": " + why;
  }
  std::string file_;
  std::size_t line_;
  std::string why_;
};

}  // namespace certimesh::io
