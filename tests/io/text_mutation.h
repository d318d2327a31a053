// Seeded random edits of a valid file's text (1-3 characters replaced, inserted or erased), for
// the properties "a damaged file only ever gives FormatError, naming the file".
#pragma once

#include <cstddef>
#include <random>
#include <string>

namespace certimesh::testing {

inline std::string mutate_text(std::string text, std::mt19937_64& rng) {
  static const std::string alphabet = "0123456789 -+.eE\n<>/=\"$abcxyzNnIiAaFf";
  const int edits = 1 + static_cast<int>(rng() % 3);
  for (int e = 0; e < edits && !text.empty(); ++e) {
    const std::size_t at = rng() % text.size();
    const char c = alphabet[rng() % alphabet.size()];
    switch (rng() % 3) {
      case 0: text[at] = c; break;
      case 1: text.insert(text.begin() + static_cast<std::ptrdiff_t>(at), c); break;
      default: text.erase(at, 1 + rng() % 8); break;
    }
  }
  return text;
}

}  // namespace certimesh::testing
