#include "front_grid_2.h"

#include <algorithm>
#include <iterator>
#include <utility>

#include <boost/function_output_iterator.hpp>
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/index/rtree.hpp>

namespace certimesh::generators::advancing_front_detail {
namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using TreePoint = bg::model::point<double, 2, bg::cs::cartesian>;
using TreeBox = bg::model::box<TreePoint>;
using Entry = std::pair<TreeBox, std::uint32_t>;

TreeBox box_of(const Point2& a, const Point2& b) {
  return TreeBox(TreePoint(std::min(a.x, b.x), std::min(a.y, b.y)), TreePoint(std::max(a.x, b.x), std::max(a.y, b.y)));
}

}  // namespace

struct FrontGrid2::Tree {
  bgi::rtree<Entry, bgi::quadratic<16>> rtree;
};

FrontGrid2::FrontGrid2() : tree_(std::make_unique<Tree>()) {}
FrontGrid2::~FrontGrid2() = default;

void FrontGrid2::insert(std::uint32_t edge, const Point2& a, const Point2& b) {
  tree_->rtree.insert(Entry{box_of(a, b), edge});
}

void FrontGrid2::erase(std::uint32_t edge, const Point2& a, const Point2& b) {
  tree_->rtree.remove(Entry{box_of(a, b), edge});
}

void FrontGrid2::collect(const Box2& query, std::vector<std::uint32_t>& out) const {
  const TreeBox q(TreePoint(query.xlo, query.ylo), TreePoint(query.xhi, query.yhi));
  tree_->rtree.query(bgi::intersects(q), boost::make_function_output_iterator([&](const Entry& e) { out.push_back(e.second); }));
}

}  // namespace certimesh::generators::advancing_front_detail
