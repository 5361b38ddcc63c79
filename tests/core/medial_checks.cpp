#include "medial_checks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <unordered_set>

namespace cadmedial::testing {

Stats statsOf(std::vector<double> v) {
  Stats s;
  s.count = v.size();
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  s.median = v[v.size() / 2];
  s.p99 = v[std::min(v.size() - 1, static_cast<std::size_t>(0.99 * v.size()))];
  s.max = v.back();
  return s;
}

BoxMedialness boxMedialness(const MedialResult& r, const Vec3& size) {
  BoxMedialness m;
  std::vector<double> tie, rad;
  for (std::size_t i = 0; i < r.vertices.size(); ++i) {
    if (r.vertexCell[i] == kNoIndex) continue;
    const Vec3& p = r.vertices[i];
    double d[6] = {p[0], size[0] - p[0], p[1], size[1] - p[1], p[2], size[2] - p[2]};
    if (*std::min_element(d, d + 6) <= 0) ++m.outside;
    std::sort(d, d + 6);
    tie.push_back(std::abs(d[1] - d[0]));
    rad.push_back(std::abs(r.radius[i] - d[0]));
  }
  m.tie = statsOf(tie);
  m.radius = statsOf(rad);
  return m;
}

double attachedShare(const MedialResult& r, const std::vector<Index>& ids) {
  if (ids.empty()) return 1.0;
  std::unordered_set<Index> used;
  for (Index s : r.vertexSample)
    if (s != kNoIndex) used.insert(s);
  std::size_t hit = 0;
  for (Index s : ids) hit += used.count(s);
  return static_cast<double>(hit) / ids.size();
}

std::string summary(const MedialResult& r) {
  const auto& c = r.counts;
  std::ostringstream o;
  o << "samples " << c.samples << " (dup " << c.duplicateSamples << "), cells " << c.delaunayCells << ", edges "
    << c.delaunayEdges << ", selected " << c.selectedFacets << " (unbounded " << c.unboundedFacets << ", inner "
    << c.innerFacets << ", outer " << c.outerFacets << "), convex " << c.convexEdgeTriangles << " (+fan " << r.forced.convexFanTriangles << "), fills "
    << c.convexFillTriangles << " (gaps unfilled " << r.forced.gapsWithoutFill << "), corner " << c.cornerTriangles << " (outer " << c.outerCornerTriangles
    << "), triplets not Delaunay " << c.tripletsNotDelaunay << ", on hull " << c.tripletsOnHull << ", sheets "
    << c.sheets << ", V/E/F " << r.topology.vertices << "/" << r.topology.edges << "/" << r.topology.polygons
    << ", b0 " << r.topology.beta0 << " b1 " << r.topology.beta1 << " b2 " << r.topology.beta2 << " core "
    << r.topology.coreSize << ", blocked " << c.walkBlockedCrossings << ", oracle " << c.oracleDisagreements << "/"
    << c.oracleChecked << "\n  times: delaunay " << r.times.delaunay << " voronoi " << r.times.voronoi << " umbrellas "
    << r.times.umbrellas << " selection " << r.times.selection << " convex " << r.times.convexEdges << " corners "
    << r.times.corners << " walk " << r.times.walk << " complex " << r.times.complex << " sheets " << r.times.sheets
    << " topology " << r.times.topology << " total " << r.times.total;
  return o.str();
}

}  // namespace cadmedial::testing
