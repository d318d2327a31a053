// Payload text of the campaign targets: words and exact doubles (C99 %a hex floats, which
// strtod reads back bit for bit; nan and inf included). Private to the library.
#pragma once

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "certimesh/fuzz/campaign/target.h"

namespace certimesh::fuzz::campaign {

inline std::string hex_double(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%a", v);
  return buffer;
}

class PayloadReader {
 public:
  explicit PayloadReader(std::string_view text) : text_(text) {}

  /// The next space-separated word; throws MalformedPayload at the end.
  std::string next_word() {
    while (pos_ < text_.size() && text_[pos_] == ' ') ++pos_;
    if (pos_ >= text_.size()) throw MalformedPayload("payload ends early (after " + std::to_string(words_) + " words)");
    const std::size_t end = std::min(text_.find(' ', pos_), text_.size());
    std::string word(text_.substr(pos_, end - pos_));
    pos_ = end;
    ++words_;
    return word;
  }

  /// The next word as a double (hex or decimal, nan, inf), read exactly.
  double next_double() {
    const std::string word = next_word();
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(word.c_str(), &end);
    if (end == word.c_str() || *end != '\0') throw MalformedPayload("word " + std::to_string(words_) + " is not a number: '" + word + "'");
    return v;
  }

  /// True when only spaces are left.
  bool at_end() const { return text_.find_first_not_of(' ', pos_) == std::string_view::npos; }

  void expect_end() {
    while (pos_ < text_.size() && text_[pos_] == ' ') ++pos_;
    if (pos_ < text_.size()) throw MalformedPayload("unexpected text after " + std::to_string(words_) + " words: '" + std::string(text_.substr(pos_)) + "'");
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t words_ = 0;
};

}  // namespace certimesh::fuzz::campaign
