#include "certimesh/topology/simplex_mesh.h"

#include <algorithm>
#include <string>

#include "certimesh/topology/local_facets.h"
#include "certimesh/topology/topology_error.h"

namespace certimesh::topology {

namespace {

std::string id_text(std::uint32_t v) { return std::to_string(v); }

}  // namespace

template <int E, int S>
typename SimplexMesh<E, S>::Key SimplexMesh<E, S>::key_of(const Facet& f) noexcept {
  Key key{};
  for (std::size_t k = 0; k < key.size(); ++k) key[k] = f[k].value;
  return sorted_key<S>(key);
}

template <int E, int S>
void SimplexMesh<E, S>::reserve(std::size_t vertices, std::size_t elements) {
  coordinates_.reserve(vertices * E);
  vertex_live_.reserve(vertices);
  vertex_degree_.reserve(vertices);
  vertex_hint_.reserve(vertices);
  element_vertices_.reserve(elements * (S + 1));
  neighbours_.reserve(elements * (S + 1));
  element_labels_.reserve(elements);
  element_live_.reserve(elements);
  // Each element holds S+1 facets, each shared by at most two: about (S+1)/2 per element.
  facets_.reserve(elements * (S + 1) / 2 + 16);
}

// --- vertices -----------------------------------------------------------------------------

template <int E, int S>
VertexId SimplexMesh<E, S>::add_vertex(const Point& p) {
  VertexId v;
  if (!free_vertices_.empty()) {
    v = free_vertices_.back();
    free_vertices_.pop_back();
  } else {
    v = VertexId{static_cast<std::uint32_t>(vertex_live_.size())};
    vertex_live_.push_back(0);
    vertex_degree_.push_back(0);
    vertex_hint_.push_back(no_element);
    coordinates_.resize(coordinates_.size() + E);
  }
  vertex_live_[v.value] = 1;
  vertex_degree_[v.value] = 0;
  vertex_hint_[v.value] = no_element;
  std::copy(p.begin(), p.end(), coordinates_.begin() + static_cast<std::ptrdiff_t>(v.value) * E);
  ++live_vertices_;
  return v;
}

template <int E, int S>
void SimplexMesh<E, S>::remove_vertex(VertexId v) {
  check_live(v);
  if (vertex_degree_[v.value] != 0)
    throw TopologyError("remove_vertex: vertex " + id_text(v.value) + " is still used by " +
                        std::to_string(vertex_degree_[v.value]) + " element(s)");
  vertex_live_[v.value] = 0;
  free_vertices_.push_back(v);
  --live_vertices_;
}

template <int E, int S>
void SimplexMesh<E, S>::move_vertex(VertexId v, const Point& p) {
  check_live(v);
  std::copy(p.begin(), p.end(), coordinates_.begin() + static_cast<std::ptrdiff_t>(v.value) * E);
}

template <int E, int S>
bool SimplexMesh<E, S>::is_live(VertexId v) const noexcept {
  return v.value < vertex_live_.size() && vertex_live_[v.value] != 0;
}

template <int E, int S>
typename SimplexMesh<E, S>::Point SimplexMesh<E, S>::point(VertexId v) const {
  check_live(v);
  Point p{};
  const auto first = coordinates_.begin() + static_cast<std::ptrdiff_t>(v.value) * E;
  std::copy(first, first + E, p.begin());
  return p;
}

template <int E, int S>
void SimplexMesh<E, S>::check_live(VertexId v) const {
  if (!is_live(v)) throw TopologyError("vertex " + id_text(v.value) + " is not a live vertex");
}

// --- elements -----------------------------------------------------------------------------

template <int E, int S>
bool SimplexMesh<E, S>::is_live(ElementId e) const noexcept {
  return e.value < element_live_.size() && element_live_[e.value] != 0;
}

template <int E, int S>
void SimplexMesh<E, S>::check_live(ElementId e) const {
  if (!is_live(e)) throw TopologyError("element " + id_text(e.value) + " is not a live element");
}

template <int E, int S>
typename SimplexMesh<E, S>::Element SimplexMesh<E, S>::vertices(ElementId e) const {
  check_live(e);
  Element out{};
  const auto first = element_vertices_.begin() + static_cast<std::ptrdiff_t>(e.value) * (S + 1);
  std::copy(first, first + (S + 1), out.begin());
  return out;
}

template <int E, int S>
ElementId SimplexMesh<E, S>::neighbour(ElementId e, int facet) const {
  check_live(e);
  return neighbours_[static_cast<std::size_t>(e.value) * (S + 1) + static_cast<std::size_t>(facet)];
}

template <int E, int S>
Label SimplexMesh<E, S>::label(ElementId e) const {
  check_live(e);
  return element_labels_[e.value];
}

template <int E, int S>
void SimplexMesh<E, S>::set_label(ElementId e, Label label) {
  check_live(e);
  element_labels_[e.value] = label;
}

template <int E, int S>
typename SimplexMesh<E, S>::Facet SimplexMesh<E, S>::facet(ElementId e, int i) const {
  const Element v = vertices(e);
  const auto local = local_facet<S>(i);
  Facet f{};
  for (std::size_t k = 0; k < f.size(); ++k) f[k] = v[static_cast<std::size_t>(local[k])];
  return f;
}

template <int E, int S>
int SimplexMesh<E, S>::local_vertex(ElementId e, VertexId v) const noexcept {
  const std::size_t base = static_cast<std::size_t>(e.value) * (S + 1);
  for (int k = 0; k <= S; ++k)
    if (element_vertices_[base + static_cast<std::size_t>(k)] == v) return k;
  return -1;
}

template <int E, int S>
int SimplexMesh<E, S>::mirror_facet(ElementId e, int i) const {
  const ElementId n = neighbour(e, i);
  if (n == no_element) return -1;
  // The facet n shares with e is the one opposite n's only vertex not on that facet.
  const Key key = key_of(facet(e, i));
  const Element nv = vertices(n);
  for (int j = 0; j <= S; ++j)
    if (!std::binary_search(key.begin(), key.end(), nv[static_cast<std::size_t>(j)].value)) return j;
  return -1;  // unreachable for a consistent mesh
}

template <int E, int S>
void SimplexMesh<E, S>::check_new_vertices(const Element& vertices) const {
  for (std::size_t a = 0; a < vertices.size(); ++a) {
    if (!is_live(vertices[a]))
      throw TopologyError("add_element: vertex " + id_text(vertices[a].value) + " (local " +
                          std::to_string(a) + ") is not a live vertex");
    for (std::size_t b = 0; b < a; ++b)
      if (vertices[a] == vertices[b])
        throw TopologyError("add_element: vertex " + id_text(vertices[a].value) +
                            " is repeated (local " + std::to_string(b) + " and " +
                            std::to_string(a) + ")");
  }
}

template <int E, int S>
typename SimplexMesh<E, S>::Key SimplexMesh<E, S>::facet_key(const Element& vertices, int i) noexcept {
  const auto local = local_facet<S>(i);
  Key key{};
  for (std::size_t k = 0; k < key.size(); ++k) key[k] = vertices[static_cast<std::size_t>(local[k])].value;
  return sorted_key<S>(key);
}

template <int E, int S>
ElementId SimplexMesh<E, S>::take_element_slot() {
  if (!free_elements_.empty()) {
    const ElementId e = free_elements_.back();
    free_elements_.pop_back();
    return e;
  }
  const ElementId e{static_cast<std::uint32_t>(element_live_.size())};
  element_live_.push_back(0);
  element_labels_.push_back(0);
  element_vertices_.resize(element_vertices_.size() + (S + 1));
  neighbours_.resize(neighbours_.size() + (S + 1), no_element);
  return e;
}

template <int E, int S>
void SimplexMesh<E, S>::count_lookup() const noexcept {
  ++lookups_;
}

template <int E, int S>
typename SimplexMesh<E, S>::FacetHolder* SimplexMesh<E, S>::find_holder(const Key& key) {
  count_lookup();
  const auto it = facets_.find(key);
  return it == facets_.end() ? nullptr : &it->second;
}

template <int E, int S>
const typename SimplexMesh<E, S>::FacetHolder* SimplexMesh<E, S>::find_holder(const Key& key) const {
  count_lookup();
  const auto it = facets_.find(key);
  return it == facets_.end() ? nullptr : &it->second;
}

template <int E, int S>
ElementId& SimplexMesh<E, S>::neighbour_slot(ElementId e, int i) noexcept {
  return neighbours_[static_cast<std::size_t>(e.value) * (S + 1) + static_cast<std::size_t>(i)];
}

template <int E, int S>
ElementId SimplexMesh<E, S>::add_element(const Element& vertices, Label label) {
  check_new_vertices(vertices);
  // One lookup per facet: find every twin first (a facet held twice refuses a third element
  // before anything changes), then link. Pointers to mapped values survive rehashing.
  std::array<Key, S + 1> keys{};
  std::array<FacetHolder*, S + 1> twins{};
  for (int i = 0; i <= S; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    keys[ui] = facet_key(vertices, i);
    twins[ui] = find_holder(keys[ui]);
    if (twins[ui] != nullptr && neighbour_slot(twins[ui]->element, twins[ui]->local) != no_element)
      throw TopologyError("add_element: facet opposite local vertex " + std::to_string(i) +
                          " is already shared by elements " + id_text(twins[ui]->element.value) +
                          " and " + id_text(neighbour_slot(twins[ui]->element, twins[ui]->local).value) +
                          " (non-manifold)");
  }
  const ElementId e = take_element_slot();
  element_live_[e.value] = 1;
  element_labels_[e.value] = label;
  std::copy(vertices.begin(), vertices.end(),
            element_vertices_.begin() + static_cast<std::ptrdiff_t>(e.value) * (S + 1));
  for (int i = 0; i <= S; ++i) {
    FacetHolder* twin = twins[static_cast<std::size_t>(i)];
    if (twin == nullptr) {
      facets_.emplace(keys[static_cast<std::size_t>(i)], FacetHolder{e, i});
      neighbour_slot(e, i) = no_element;
    } else {
      neighbour_slot(e, i) = twin->element;
      neighbour_slot(twin->element, twin->local) = e;
    }
  }
  for (const VertexId v : vertices) {
    ++vertex_degree_[v.value];
    vertex_hint_[v.value] = e;
  }
  ++live_elements_;
  return e;
}

template <int E, int S>
void SimplexMesh<E, S>::unlink_facet(ElementId e, const Element& vertices, int i) {
  const Key key = facet_key(vertices, i);
  count_lookup();
  const auto it = facets_.find(key);
  const ElementId n = neighbour_slot(e, i);
  if (n == no_element) {
    facets_.erase(it);
    return;
  }
  // The twin's local index: its only vertex not on the shared facet.
  int j = 0;
  while (std::binary_search(key.begin(), key.end(),
                            element_vertices_[static_cast<std::size_t>(n.value) * (S + 1) + static_cast<std::size_t>(j)].value))
    ++j;
  neighbour_slot(n, j) = no_element;
  neighbour_slot(e, i) = no_element;
  it->second = FacetHolder{n, j};
}

template <int E, int S>
void SimplexMesh<E, S>::refresh_hint_after_removal(ElementId removed, VertexId v) {
  --vertex_degree_[v.value];
  if (vertex_hint_[v.value] != removed) return;
  vertex_hint_[v.value] = no_element;
  if (vertex_degree_[v.value] == 0) return;
  // Any neighbour across a facet through v uses v (facet i contains v unless v is local i).
  const int local_v = local_vertex(removed, v);
  for (int i = 0; i <= S; ++i) {
    if (i == local_v) continue;
    const ElementId n = neighbours_[static_cast<std::size_t>(removed.value) * (S + 1) + static_cast<std::size_t>(i)];
    if (n != no_element) {
      vertex_hint_[v.value] = n;
      return;
    }
  }
}

template <int E, int S>
void SimplexMesh<E, S>::remove_element(ElementId e) {
  check_live(e);
  const Element vs = vertices(e);
  // Hints first, while the removed element still knows its neighbours.
  for (const VertexId v : vs) refresh_hint_after_removal(e, v);
  for (int i = 0; i <= S; ++i) unlink_facet(e, vs, i);
  element_live_[e.value] = 0;
  free_elements_.push_back(e);
  --live_elements_;
}

template <int E, int S>
std::optional<typename SimplexMesh<E, S>::FacetRef> SimplexMesh<E, S>::find_facet(const Facet& f) const {
  const FacetHolder* holder = find_holder(key_of(f));
  if (holder == nullptr) return std::nullopt;
  return FacetRef{holder->element, holder->local};
}

// --- facet labels -------------------------------------------------------------------------

template <int E, int S>
void SimplexMesh<E, S>::set_facet_label(const Facet& f, Label label) {
  const Key key = key_of(f);
  const auto it = facet_labels_.find(key);
  const int change = (label != 0) - (it != facet_labels_.end());
  if (label == 0) {
    if (it != facet_labels_.end()) facet_labels_.erase(it);
  } else {
    facet_labels_[key] = label;
  }
  if (change == 0) return;
  for (const VertexId v : f) {
    if (labelled_facets_at_.size() <= v.value) labelled_facets_at_.resize(v.value + 1, 0);
    labelled_facets_at_[v.value] += static_cast<std::uint32_t>(change);  // wraps back on -1
  }
}

template <int E, int S>
Label SimplexMesh<E, S>::facet_label(const Facet& f) const {
  // Most facets have a vertex on no labelled facet: answered without hashing.
  for (const VertexId v : f)
    if (v.value >= labelled_facets_at_.size() || labelled_facets_at_[v.value] == 0) return 0;
  const auto it = facet_labels_.find(key_of(f));
  return it == facet_labels_.end() ? 0 : it->second;
}

template class SimplexMesh<2, 2>;
template class SimplexMesh<3, 2>;
template class SimplexMesh<3, 3>;

}  // namespace certimesh::topology
