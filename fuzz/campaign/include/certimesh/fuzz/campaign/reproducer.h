// The reproducer file of a finding: small, line-based text, readable by a person and
// replayable by `certimesh fuzz --replay FILE`.
//
//   certimesh-fuzz-reproducer 1
//   target predicates
//   seed 0x2a
//   case 1234
//   case-seed 0x8f1e...
//   message orient2d: the filter contradicts the exact sign
//   payload orient2d 0x1.8p+0 0x1p-3 ...
//
// The payload (the input, doubles as %a hex floats, exact) is what replay() reads; seed and
// case re-derive it through the generators, which may change between versions.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace certimesh::fuzz::campaign {

inline constexpr int kReproducerFormatVersion = 1;

struct Reproducer {
  int format_version = kReproducerFormatVersion;
  std::string target;
  std::uint64_t seed = 0;        // the campaign's K
  std::uint64_t case_index = 0;  // i
  std::uint64_t case_seed = 0;   // splitmix64(K ^ splitmix64(i))
  std::string message;
  std::string payload;
  friend bool operator==(const Reproducer&, const Reproducer&) = default;
};

/// A reproducer text that cannot be read; what() is "line N: why".
class MalformedReproducer : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The file's text. Throws std::invalid_argument when a field holds a newline.
std::string write_reproducer(const Reproducer& r);

/// Reads write_reproducer's text back. Fields in any order after the header line, each
/// once; blank lines and `#` comments skipped. Throws MalformedReproducer.
Reproducer parse_reproducer(std::string_view text);

}  // namespace certimesh::fuzz::campaign
