#include "certimesh/fuzz/campaign/reproducer.h"

#include <charconv>
#include <cstdio>
#include <optional>
#include <stdexcept>

namespace certimesh::fuzz::campaign {

namespace {

constexpr std::string_view kMagic = "certimesh-fuzz-reproducer";

std::string hex(std::uint64_t v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "0x%llx", static_cast<unsigned long long>(v));
  return buffer;
}

[[noreturn]] void malformed(std::size_t line, const std::string& why) {
  throw MalformedReproducer("line " + std::to_string(line) + ": " + why);
}

// A decimal or 0x-prefixed hexadecimal unsigned 64-bit number, the whole of `text`.
std::optional<std::uint64_t> parse_u64(std::string_view text) {
  int base = 10;
  if (text.starts_with("0x") || text.starts_with("0X")) {
    text.remove_prefix(2);
    base = 16;
  }
  if (text.empty()) return std::nullopt;
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v, base);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return v;
}

}  // namespace

std::string write_reproducer(const Reproducer& r) {
  for (const std::string* field : {&r.target, &r.message, &r.payload})
    if (field->find_first_of("\r\n") != std::string::npos)
      throw std::invalid_argument("write_reproducer: a field holds a line break");
  std::string out;
  out += std::string(kMagic) + " " + std::to_string(r.format_version) + "\n";
  out += "target " + r.target + "\n";
  out += "seed " + hex(r.seed) + "\n";
  out += "case " + std::to_string(r.case_index) + "\n";
  out += "case-seed " + hex(r.case_seed) + "\n";
  out += "message " + r.message + "\n";
  out += "payload " + r.payload + "\n";
  return out;
}

Reproducer parse_reproducer(std::string_view text) {
  Reproducer r;
  bool header = false;
  unsigned seen = 0;  // bit per field
  static constexpr std::string_view fields[] = {"target", "seed", "case", "case-seed", "message", "payload"};
  std::size_t line_number = 0;
  while (!text.empty()) {
    const std::size_t eol = text.find('\n');
    std::string_view line = text.substr(0, eol);
    text.remove_prefix(eol == std::string_view::npos ? text.size() : eol + 1);
    ++line_number;
    if (line.ends_with('\r')) line.remove_suffix(1);
    if (line.empty() || line.starts_with('#')) continue;
    const std::size_t space = line.find(' ');
    const std::string_view key = line.substr(0, space);
    const std::string_view value = space == std::string_view::npos ? std::string_view{} : line.substr(space + 1);
    if (!header) {
      if (key != kMagic) malformed(line_number, "not a certimesh fuzz reproducer (expected '" + std::string(kMagic) + " 1')");
      const auto v = parse_u64(value);
      if (!v) malformed(line_number, "the format version is not a number");
      if (*v != static_cast<std::uint64_t>(kReproducerFormatVersion))
        malformed(line_number, "format version " + std::string(value) + " (this build reads version " +
                                   std::to_string(kReproducerFormatVersion) + ")");
      r.format_version = kReproducerFormatVersion;
      header = true;
      continue;
    }
    std::size_t f = 0;
    while (f < std::size(fields) && fields[f] != key) ++f;
    if (f == std::size(fields)) malformed(line_number, "unknown field '" + std::string(key) + "'");
    if (seen & (1u << f)) malformed(line_number, "field '" + std::string(key) + "' given twice");
    seen |= 1u << f;
    if (value.empty() && key != "message") malformed(line_number, "field '" + std::string(key) + "' has no value");
    const auto number = [&]() {
      const auto v = parse_u64(value);
      if (!v) malformed(line_number, "field '" + std::string(key) + "' is not a 64-bit number: '" + std::string(value) + "'");
      return *v;
    };
    if (key == "target") r.target = value;
    else if (key == "seed") r.seed = number();
    else if (key == "case") r.case_index = number();
    else if (key == "case-seed") r.case_seed = number();
    else if (key == "message") r.message = value;
    else r.payload = value;
  }
  if (!header) malformed(line_number, "empty file (expected '" + std::string(kMagic) + " 1')");
  for (std::size_t f = 0; f < std::size(fields); ++f)
    if (!(seen & (1u << f))) malformed(line_number, "field '" + std::string(fields[f]) + "' missing");
  return r;
}

}  // namespace certimesh::fuzz::campaign
