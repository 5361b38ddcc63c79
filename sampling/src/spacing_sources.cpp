#include "spacing_sources.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include <CGAL/Orthogonal_incremental_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

namespace cadmedial {

namespace {
using Kernel = CGAL::Simple_cartesian<double>;
using PointWithSpacing = std::tuple<Kernel::Point_3, double>;
using PointOf = CGAL::Nth_of_tuple_property_map<0, PointWithSpacing>;
using Traits = CGAL::Search_traits_adapter<PointWithSpacing, PointOf, CGAL::Search_traits_3<Kernel>>;
using Distance = CGAL::Distance_adapter<PointWithSpacing, PointOf, CGAL::Euclidean_distance<CGAL::Search_traits_3<Kernel>>>;
using NearestFirst = CGAL::Orthogonal_incremental_neighbor_search<Traits, Distance>;
}  // namespace

struct SpacingSources::Tree {
  NearestFirst::Tree tree;
};

SpacingSources::SpacingSources(std::vector<Source> sources, double grading)
    : tree_(std::make_unique<Tree>()),
      grading_(grading),
      finest_(std::numeric_limits<double>::infinity()) {
  std::vector<PointWithSpacing> points;
  points.reserve(sources.size());
  for (const Source& s : sources) {
    points.emplace_back(Kernel::Point_3(s.point.X(), s.point.Y(), s.point.Z()), s.spacing);
    finest_ = std::min(finest_, s.spacing);
  }
  tree_->tree.insert(points.begin(), points.end());
  tree_->tree.build();  // now rather than lazily inside the first (const) query
}

SpacingSources::~SpacingSources() = default;

double SpacingSources::allowedNear(const gp_Pnt& p, double slack, double upTo) const {
  if (tree_->tree.size() == 0) return upTo;
  double best = upTo;
  NearestFirst search(tree_->tree, Kernel::Point_3(p.X(), p.Y(), p.Z()), 0.0, true, Distance());
  for (auto it = search.begin(); it != search.end(); ++it) {
    const double reach = std::max(0.0, std::sqrt(it->second) - slack);
    // Every source from here on is at least this far: none can beat `best`.
    if (finest_ + grading_ * reach >= best) break;
    best = std::min(best, std::get<1>(it->first) + grading_ * reach);
  }
  return best;
}

}  // namespace cadmedial
