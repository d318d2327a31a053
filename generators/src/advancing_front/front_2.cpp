#include "front_2.h"

#include <algorithm>

namespace certimesh::generators::advancing_front_detail {

void Front2::reserve(std::size_t vertices, std::size_t edges) {
  edges_.reserve(edges);
  first_out_.reserve(vertices);
  first_in_.reserve(vertices);
  heap_.reserve(edges);
}

void Front2::grow_vertices(std::size_t count) {
  if (first_out_.size() < count) first_out_.resize(count, no_id);
  if (first_in_.size() < count) first_in_.resize(count, no_id);
}

std::uint32_t Front2::insert(std::uint32_t a, std::uint32_t b, std::uint32_t rank, double length2) {
  std::uint32_t id = 0;
  if (free_slots_.empty()) {
    id = static_cast<std::uint32_t>(edges_.size());
    edges_.emplace_back();
  } else {
    id = free_slots_.back();
    free_slots_.pop_back();
  }
  edges_[id] = Edge{a, b, first_out_[a], first_in_[b], true};
  first_out_[a] = id;
  first_in_[b] = id;
  heap_.push_back(HeapEntry{length2, rank, a, b, id});
  std::push_heap(heap_.begin(), heap_.end(), after);
  ++live_;
  return id;
}

void Front2::erase(std::uint32_t e) {
  Edge& edge = edges_[e];
  std::uint32_t* link = &first_out_[edge.a];
  while (*link != e) link = &edges_[*link].next_out;
  *link = edge.next_out;
  link = &first_in_[edge.b];
  while (*link != e) link = &edges_[*link].next_in;
  *link = edge.next_in;
  edge.alive = false;
  edge.next_out = edge.next_in = no_id;
  free_slots_.push_back(e);
  --live_;
}

std::uint32_t Front2::find(std::uint32_t a, std::uint32_t b) const {
  for (std::uint32_t e = first_out_[a]; e != no_id; e = edges_[e].next_out)
    if (edges_[e].b == b) return e;
  return no_id;
}

std::uint32_t Front2::shortest() {
  const auto stale = [&](const HeapEntry& h) {
    const Edge& e = edges_[h.edge];
    return !e.alive || e.a != h.a || e.b != h.b;
  };
  while (!heap_.empty() && stale(heap_.front())) {
    std::pop_heap(heap_.begin(), heap_.end(), after);
    heap_.pop_back();
  }
  return heap_.empty() ? no_id : heap_.front().edge;
}

}  // namespace certimesh::generators::advancing_front_detail
