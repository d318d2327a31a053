// A line-aware tokenizer over a whole text file held in memory, shared by the text readers.
// Every failure goes through fail(), which names the file and the current line. Numbers are
// parsed with std::from_chars (exact round trip for doubles; no locale), NaN and Inf refused.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <string_view>

#include "certimesh/io/format_error.h"

namespace certimesh::io::detail {

class TextReader {
 public:
  /// Reads the whole file; throws FormatError (line 0) when it cannot be opened.
  explicit TextReader(const std::filesystem::path& path);
  /// For tests and in-memory parsing: `name` is what errors call the file.
  TextReader(std::string name, std::string contents);

  /// Characters that begin a comment running to the end of the line ('#' by default).
  void set_comment_chars(std::string_view chars) { comment_chars_ = chars; }

  /// The next whitespace-separated token, skipping comments and line breaks; empty at the end.
  std::string_view next_token();
  /// The next token; fail("unexpected end of file, expected <what>") at the end.
  std::string_view expect_token(std::string_view what);
  /// The rest of the current line (after the last token read), without the line break.
  std::string_view rest_of_line();
  /// True when only whitespace and comments remain.
  bool at_end();

  /// A finite double (decimal or hex float); fails naming `what` on NaN, Inf, out of range.
  double read_double(std::string_view what);
  /// An integer in [lo, hi]; fails naming `what` otherwise.
  std::int64_t read_integer(std::string_view what, std::int64_t lo, std::int64_t hi);
  /// A count of records that each need at least `min_bytes_per_record` more bytes: refuses
  /// counts the rest of the file cannot hold, so a hostile header never drives an allocation.
  std::size_t read_count(std::string_view what, std::size_t min_bytes_per_record);
  /// The check read_count does, for a count read before its record size was known.
  void check_count_fits(std::string_view what, std::size_t count, std::size_t min_bytes_per_record) const;

  /// Line records (Triangle/TetGen files, one record per line): after begin_record(), tokens
  /// come only from the line where the record starts -- a short line fails as "line ends
  /// before <what>" instead of silently taking the next line's first field -- and
  /// end_record() fails when the line holds more fields than the record.
  void begin_record();
  void end_record(std::string_view what);
  /// Inside a record: true when another field follows on the record's line.
  bool record_has_more();

  /// A token as error messages quote it: at most 40 characters, control bytes as '?'.
  static std::string quoted(std::string_view token);

  /// Line of the last token read (1-based).
  std::size_t line() const { return token_line_; }
  std::size_t remaining_bytes() const { return contents_.size() - pos_; }
  const std::string& name() const { return name_; }

  [[noreturn]] void fail(const std::string& why) const { throw FormatError(name_, token_line_, why); }

 private:
  void skip_blanks_and_comments();
  void skip_blanks_on_line();

  std::string name_;
  std::string contents_;
  std::string_view comment_chars_ = "#";
  std::size_t pos_ = 0;
  std::size_t line_ = 1;        // line of pos_
  std::size_t token_line_ = 1;  // line of the last token returned
  bool in_record_ = false;      // between begin_record() and end_record()
};

}  // namespace certimesh::io::detail
