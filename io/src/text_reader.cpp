#include "text_reader.h"

#include <fstream>
#include <sstream>

namespace certimesh::io::detail {

namespace {
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }
bool is_sign(char c) { return c == '+' || c == '-'; }
}  // namespace

TextReader::TextReader(const std::filesystem::path& path) : name_(path.string()) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FormatError(name_, 0, "cannot open the file for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw FormatError(name_, 0, "read error");
  contents_ = std::move(buffer).str();
}

TextReader::TextReader(std::string name, std::string contents)
    : name_(std::move(name)), contents_(std::move(contents)) {}

std::string TextReader::quoted(std::string_view token) {
  // A hostile file may hold a megabyte-long token or binary bytes: the message stays short
  // and printable.
  constexpr std::size_t kMaxShown = 40;
  std::string shown;
  for (const char c : token.substr(0, kMaxShown)) {
    const auto u = static_cast<unsigned char>(c);
    shown += (u < 0x20 || u >= 0x7f) ? '?' : c;
  }
  if (token.size() > kMaxShown) shown += "...";
  return "'" + shown + "'";
}

void TextReader::skip_blanks_and_comments() {
  while (pos_ < contents_.size()) {
    const char c = contents_[pos_];
    if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (is_space(c)) {
      ++pos_;
    } else if (comment_chars_.find(c) != std::string_view::npos) {
      while (pos_ < contents_.size() && contents_[pos_] != '\n') ++pos_;
    } else {
      return;
    }
  }
}

void TextReader::skip_blanks_on_line() {
  while (pos_ < contents_.size() && contents_[pos_] != '\n') {
    const char c = contents_[pos_];
    if (is_space(c)) {
      ++pos_;
    } else if (comment_chars_.find(c) != std::string_view::npos) {
      while (pos_ < contents_.size() && contents_[pos_] != '\n') ++pos_;
    } else {
      return;
    }
  }
}

std::string_view TextReader::next_token() {
  if (in_record_) {
    skip_blanks_on_line();
    if (pos_ >= contents_.size() || contents_[pos_] == '\n') return {};
  } else {
    skip_blanks_and_comments();
  }
  token_line_ = line_;
  const std::size_t begin = pos_;
  while (pos_ < contents_.size() && !is_space(contents_[pos_]) &&
         comment_chars_.find(contents_[pos_]) == std::string_view::npos) {
    ++pos_;
  }
  return std::string_view(contents_).substr(begin, pos_ - begin);
}

std::string_view TextReader::expect_token(std::string_view what) {
  const std::string_view token = next_token();
  if (token.empty()) {
    if (in_record_ && pos_ < contents_.size()) fail("line ends before " + std::string(what));
    fail("unexpected end of file, expected " + std::string(what));
  }
  return token;
}

void TextReader::begin_record() {
  in_record_ = false;
  skip_blanks_and_comments();
  token_line_ = line_;
  in_record_ = true;
}

bool TextReader::record_has_more() {
  skip_blanks_on_line();
  return pos_ < contents_.size() && contents_[pos_] != '\n';
}

void TextReader::end_record(std::string_view what) {
  const std::string_view extra = next_token();
  if (!extra.empty()) {
    fail("unexpected field " + quoted(extra) + " after " + std::string(what));
  }
  in_record_ = false;
}

std::string_view TextReader::rest_of_line() {
  const std::size_t begin = pos_;
  while (pos_ < contents_.size() && contents_[pos_] != '\n') ++pos_;
  std::string_view rest = std::string_view(contents_).substr(begin, pos_ - begin);
  if (!rest.empty() && rest.back() == '\r') rest.remove_suffix(1);
  return rest;
}

bool TextReader::at_end() {
  if (in_record_) return !record_has_more();
  skip_blanks_and_comments();
  return pos_ >= contents_.size();
}

double TextReader::read_double(std::string_view what) {
  std::string_view token = expect_token(what);
  std::string_view digits = token;
  bool negative = false;
  if (!digits.empty() && is_sign(digits.front())) {
    negative = digits.front() == '-';
    digits.remove_prefix(1);
  }
  // from_chars accepts a leading '-' itself: a second sign ("--1", "+-1") is malformed.
  if (!digits.empty() && is_sign(digits.front())) {
    fail("expected " + std::string(what) + " (a number), got " + quoted(token));
  }
  double value = 0.0;
  std::from_chars_result result{};
  if (digits.size() > 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) {
    digits.remove_prefix(2);
    result = std::from_chars(digits.data(), digits.data() + digits.size(), value, std::chars_format::hex);
  } else {
    result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  }
  if (result.ec == std::errc::result_out_of_range) {
    fail(std::string(what) + " " + quoted(token) + " is out of the range of a double");
  }
  if (result.ec != std::errc() || result.ptr != digits.data() + digits.size()) {
    fail("expected " + std::string(what) + " (a number), got " + quoted(token));
  }
  if (!std::isfinite(value)) {
    fail(std::string(what) + " is not finite (" + quoted(token) + ")");
  }
  return negative ? -value : value;
}

std::int64_t TextReader::read_integer(std::string_view what, std::int64_t lo, std::int64_t hi) {
  std::string_view token = expect_token(what);
  std::string_view digits = token;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  // from_chars accepts a leading '-' itself: "+-3" must not pass as -3.
  if (!digits.empty() && is_sign(digits.front()) && token.front() == '+') {
    fail("expected " + std::string(what) + " (an integer), got " + quoted(token));
  }
  std::int64_t value = 0;
  const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (result.ec == std::errc::result_out_of_range) {
    fail(std::string(what) + " " + quoted(token) + " is out of range");
  }
  if (result.ec != std::errc() || result.ptr != digits.data() + digits.size()) {
    fail("expected " + std::string(what) + " (an integer), got " + quoted(token));
  }
  if (value < lo || value > hi) {
    fail(std::string(what) + " " + std::to_string(value) + " is outside [" + std::to_string(lo) +
         ", " + std::to_string(hi) + "]");
  }
  return value;
}

void TextReader::check_count_fits(std::string_view what, std::size_t count,
                                  std::size_t min_bytes_per_record) const {
  const std::size_t per = min_bytes_per_record == 0 ? 1 : min_bytes_per_record;
  if (count > remaining_bytes() / per) {
    fail(std::string(what) + " " + std::to_string(count) + " cannot fit in the " +
         std::to_string(remaining_bytes()) + " bytes left in the file");
  }
}

std::size_t TextReader::read_count(std::string_view what, std::size_t min_bytes_per_record) {
  const auto count = static_cast<std::size_t>(
      read_integer(what, 0, std::numeric_limits<std::int64_t>::max()));
  check_count_fits(what, count, min_bytes_per_record);
  return count;
}

}  // namespace certimesh::io::detail
