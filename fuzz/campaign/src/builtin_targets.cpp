#include "certimesh/fuzz/campaign/delaunay2d_target.h"
#include "certimesh/fuzz/campaign/intersection_target.h"
#include "certimesh/fuzz/campaign/mesh2d_target.h"
#include "certimesh/fuzz/campaign/predicates_target.h"
#include "certimesh/fuzz/campaign/readers_target.h"
#include "certimesh/fuzz/campaign/target.h"

namespace certimesh::fuzz::campaign {

TargetRegistry builtin_targets() {
  TargetRegistry r;
  r.add(make_predicates_target());
  r.add(make_intersection_target());
  r.add(make_readers_target());
  r.add(make_delaunay2d_target());
  r.add(make_mesh2d_target());
  return r;
}

}  // namespace certimesh::fuzz::campaign
