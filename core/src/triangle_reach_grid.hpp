// Private to core: how far a point inside a reconstruction triangle can be
// from that triangle's nearest corner, as a maximum per cell of a coarse
// grid. reconstruction_sides.cpp uses it to link two Voronoi vertices
// without a segment query when no triangle can reach their segment.
//
// Why it is sound: a point q inside triangle t is within reach(t) of one of
// t's corners, and those are samples, so q's nearest sample is within
// reach(t). A segment whose every point is farther than that from all
// samples meets no triangle t in a grid cell it passes through (q lies in
// t's box and in the segment's box, so in a cell both cover).
//
// reach(t): for a triangle with no obtuse angle, its circumradius (q lies in
// one of the three kites corner-midpoint-circumcentre-midpoint, all within
// R of that corner); for an obtuse one, sqrt((L/2)² + height²) with L the
// longest edge and height that of the obtuse corner over it (q projects
// onto the longest edge, nearer one of its ends by at most L/2 along, and
// is no farther from it across than the obtuse corner).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include <CGAL/Bbox_3.h>

#include "triangle_soup_tree.hpp"

namespace cadmedial::soup {

class TriangleReachGrid {
 public:
  // About half as many cells as triangles, at most 64 a side (surface
  // triangles crowd into the cells the surface crosses). With `deviation`
  // (one value per triangle), each cell also keeps the largest deviation
  // of its triangles (deviationWithin).
  explicit TriangleReachGrid(const Triangles& triangles, const std::vector<double>& deviation = {}) {
    if (triangles.empty()) return;
    box_ = triangles.front().bbox();
    for (const auto& t : triangles) box_ += t.bbox();
    const double extent = std::max({box_.xmax() - box_.xmin(), box_.ymax() - box_.ymin(), box_.zmax() - box_.zmin()});
    const double side = std::cbrt(static_cast<double>(triangles.size()) / 2);
    n_ = static_cast<int>(std::clamp(side, 1.0, 64.0));
    if (!(extent > 0)) n_ = 1;
    for (int k = 0; k < 3; ++k) {
      const double span = box_.max(k) - box_.min(k);
      scale_[k] = span > 0 ? n_ / span : 0;
    }
    const bool withDeviation = deviation.size() == triangles.size();
    reach_.assign(static_cast<std::size_t>(n_) * n_ * n_, 0.0);
    if (withDeviation) deviation_.assign(reach_.size(), 0.0);
    for (std::size_t id = 0; id < triangles.size(); ++id) {
      const auto& t = triangles[id];
      const double r = reach(t);
      const CGAL::Bbox_3 b = t.bbox();
      int lo[3], hi[3];
      cellRange(b, lo, hi);
      for (int i = lo[0]; i <= hi[0]; ++i)
        for (int j = lo[1]; j <= hi[1]; ++j)
          for (int k = lo[2]; k <= hi[2]; ++k) {
            const std::size_t cell = index(i, j, k);
            reach_[cell] = std::max(reach_[cell], r);
            if (withDeviation) deviation_[cell] = std::max(deviation_[cell], deviation[id]);
          }
    }
  }

  // The largest reach of the triangles in the cells the box [lo, hi] meets
  // (0 where there are none); +inf when that box covers more than maxCells
  // cells (not worth scanning: the caller queries the tree).
  double reachWithin(const CGAL::Bbox_3& b, int maxCells = 64) const { return mostWithin(reach_, b, maxCells); }

  // The same for the triangles' deviations (+inf without them). A triangle
  // t with a point within d_t of p lies in a cell that the cube of
  // half-side d_t around p meets, so d_t <= deviationWithin(any larger
  // cube around p): the near test of reconstruction_sides.cpp shrinks its
  // cube from the largest deviation anywhere to this.
  double deviationWithin(const CGAL::Bbox_3& b, int maxCells = 64) const {
    if (deviation_.empty() && !reach_.empty()) return std::numeric_limits<double>::infinity();
    return mostWithin(deviation_, b, maxCells);
  }

  static double reach(const Kernel::Triangle_3& t) {
    double edge2[3];  // squared length of the edge opposite corner k
    for (int k = 0; k < 3; ++k) edge2[k] = CGAL::squared_distance(t[(k + 1) % 3], t[(k + 2) % 3]);
    const double longest2 = std::max({edge2[0], edge2[1], edge2[2]});
    const double area2 = CGAL::squared_area(t[0], t[1], t[2]);
    // Obtuse at the corner opposite the longest edge L iff L² > b² + c²:
    // within L/2 along and the height 2 area / L across.
    if (2 * longest2 > edge2[0] + edge2[1] + edge2[2]) return std::sqrt(longest2 / 4 + 4 * area2 / longest2);
    // R = abc / (4 area), which is at least L/2 here: the clamp keeps a
    // needle's rounded area from making it smaller. No area left means all
    // corners coincide.
    if (!(area2 > 0)) return std::sqrt(longest2);
    const double circumradius = std::sqrt(edge2[0] * edge2[1] * edge2[2] / (16 * area2));
    return std::clamp(circumradius, std::sqrt(longest2) / 2, std::sqrt(longest2));
  }

 private:
  double mostWithin(const std::vector<double>& values, const CGAL::Bbox_3& b, int maxCells) const {
    if (values.empty() || b.xmax() < box_.xmin() || b.xmin() > box_.xmax() || b.ymax() < box_.ymin() ||
        b.ymin() > box_.ymax() || b.zmax() < box_.zmin() || b.zmin() > box_.zmax())
      return 0;
    int lo[3], hi[3];
    cellRange(b, lo, hi);
    if ((hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1) > maxCells)
      return std::numeric_limits<double>::infinity();
    double most = 0;
    for (int i = lo[0]; i <= hi[0]; ++i)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int k = lo[2]; k <= hi[2]; ++k) most = std::max(most, values[index(i, j, k)]);
    return most;
  }
  void cellRange(const CGAL::Bbox_3& b, int lo[3], int hi[3]) const {
    for (int k = 0; k < 3; ++k) {
      lo[k] = cellOf(b.min(k), k);
      hi[k] = cellOf(b.max(k), k);
    }
  }
  // Monotone in x, clamped to the grid: a point in two boxes falls in a cell
  // of both boxes' ranges.
  int cellOf(double x, int k) const {
    const double c = std::floor((x - box_.min(k)) * scale_[k]);
    return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(n_ - 1)));
  }
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(i) * n_ + j) * n_ + k;
  }
  CGAL::Bbox_3 box_;
  int n_ = 0;
  double scale_[3] = {0, 0, 0};
  std::vector<double> reach_;
  std::vector<double> deviation_;  // empty unless given
};

}  // namespace cadmedial::soup
