// Compressed sparse rows: the monograph's "flat list" (§2.3, iVT/nVT) for an incidence
// whose rows have varying length, e.g. vertex -> elements. Row r is
// entries[offsets[r] .. offsets[r+1]); offsets has row_count()+1 entries and starts at 0
// (the book stores end pointers only; the leading 0 saves the special case for row 1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace certimesh::topology {

struct Csr {
  std::vector<std::uint32_t> offsets{0};
  std::vector<std::uint32_t> entries;

  std::size_t row_count() const noexcept { return offsets.size() - 1; }
  std::span<const std::uint32_t> row(std::size_t r) const noexcept {
    return {entries.data() + offsets[r], offsets[r + 1] - offsets[r]};
  }
};

/// Inverts a fixed-arity incidence (item s -> columns incidence[s*arity .. s*arity+arity)),
/// e.g. element -> vertices, into column -> items, by the two-pass counting sort of the
/// monograph's Algorithm 3: O(items + columns), no comparison sort. Each row lists its items
/// in increasing order (deterministic; the book's variant fills rows from the back and gets
/// decreasing order). Items with live[s] == 0 are skipped when `live` is not empty.
/// Throws std::invalid_argument if a column index is >= column_count.
Csr invert_incidence(std::span<const std::uint32_t> incidence, std::size_t arity,
                     std::size_t column_count, std::span<const std::uint8_t> live = {});

/// Inverts a CSR incidence (row -> columns) into column -> rows, by the same counting sort.
Csr invert_csr(const Csr& csr, std::size_t column_count);

}  // namespace certimesh::topology
