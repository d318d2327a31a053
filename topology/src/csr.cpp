#include "certimesh/topology/csr.h"

#include <stdexcept>
#include <string>

namespace certimesh::topology {

namespace {

// Pass 1 of Algorithm 3 done; turns counts into start offsets (exclusive prefix sum).
void counts_to_offsets(std::vector<std::uint32_t>& offsets) {
  std::uint32_t running = 0;
  for (std::uint32_t& o : offsets) {
    const std::uint32_t count = o;
    o = running;
    running += count;
  }
}

void check_column(std::uint32_t column, std::size_t column_count, std::size_t item) {
  if (column >= column_count)
    throw std::invalid_argument("invert_incidence: item " + std::to_string(item) + " names column " +
                                std::to_string(column) + ", but there are only " +
                                std::to_string(column_count));
}

}  // namespace

Csr invert_incidence(std::span<const std::uint32_t> incidence, std::size_t arity,
                     std::size_t column_count, std::span<const std::uint8_t> live) {
  const std::size_t items = arity == 0 ? 0 : incidence.size() / arity;
  auto is_live = [&](std::size_t s) { return live.empty() || live[s] != 0; };
  Csr out;
  out.offsets.assign(column_count + 1, 0);
  for (std::size_t s = 0; s < items; ++s) {
    if (!is_live(s)) continue;
    for (std::size_t k = 0; k < arity; ++k) {
      const std::uint32_t c = incidence[s * arity + k];
      check_column(c, column_count, s);
      ++out.offsets[c];
    }
  }
  counts_to_offsets(out.offsets);
  out.entries.resize(out.offsets[column_count]);
  // Pass 2: place every item at the cursor of its column; items come in increasing order.
  std::vector<std::uint32_t> cursor(out.offsets.begin(), out.offsets.end() - 1);
  for (std::size_t s = 0; s < items; ++s) {
    if (!is_live(s)) continue;
    for (std::size_t k = 0; k < arity; ++k)
      out.entries[cursor[incidence[s * arity + k]]++] = static_cast<std::uint32_t>(s);
  }
  return out;
}

Csr invert_csr(const Csr& csr, std::size_t column_count) {
  Csr out;
  out.offsets.assign(column_count + 1, 0);
  for (std::size_t r = 0; r < csr.row_count(); ++r)
    for (const std::uint32_t c : csr.row(r)) {
      check_column(c, column_count, r);
      ++out.offsets[c];
    }
  counts_to_offsets(out.offsets);
  out.entries.resize(out.offsets[column_count]);
  std::vector<std::uint32_t> cursor(out.offsets.begin(), out.offsets.end() - 1);
  for (std::size_t r = 0; r < csr.row_count(); ++r)
    for (const std::uint32_t c : csr.row(r)) out.entries[cursor[c]++] = static_cast<std::uint32_t>(r);
  return out;
}

}  // namespace certimesh::topology
