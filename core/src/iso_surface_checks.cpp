// Self-intersections of an iso-parametric surface (issue #4: "no
// self-intersections", checked with CGAL's own test). The surface is a
// triangle soup over indexed points; CGAL's test wants a polygon mesh, so
// the soup is oriented and made manifold first (non-manifold vertices are
// duplicated by CGAL's soup repair, which can only add reported pairs of
// faces touching at such a vertex, never hide a crossing).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>

#include "cadmedial/pair_mesh.hpp"

namespace cadmedial {

namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

struct Check {
  IsoSurfaceIntersections result;
  std::vector<std::size_t> crossingTriangles;  // indices into iso.triangles, each once
};

// `key` identifies equal positions exactly (equal inputs of the same
// construction); `point(i)` builds iso point i in Kernel. Only pairs of
// triangles with checked[k] set are tested (all when `checked` is empty);
// the others still weld and orient with the rest.
template <class Kernel, class Key, class KeyOf, class PointOf>
Check check(const IsoSurface& iso, KeyOf keyOf, PointOf pointOf, const std::vector<std::uint8_t>& checked = {}) {
  using Mesh = CGAL::Surface_mesh<typename Kernel::Point_3>;
  Check out;
  IsoSurfaceIntersections& result = out.result;
  if (iso.triangles.empty()) return out;
  // Flat elements (cospherical samples give coincident Voronoi nodes) cut
  // into triangles whose corners coincide in space under different indices:
  // weld equal positions, drop triangles that collapse, and drop pairs of
  // opposite copies of one triangle (the two faces of a zero-thickness cut).
  // What is left touches only where it shares vertices, or truly crosses.
  std::map<Key, std::size_t> weldedIndex;
  std::vector<std::size_t> welded(iso.points.size());
  std::vector<typename Kernel::Point_3> points;
  for (std::size_t i = 0; i < iso.points.size(); ++i) {
    auto [it, fresh] = weldedIndex.emplace(keyOf(i), points.size());
    if (fresh) points.push_back(pointOf(i));
    welded[i] = it->second;
  }
  std::map<std::array<std::size_t, 3>, std::vector<std::size_t>> byCorners;  // sorted corners -> faces
  std::vector<std::array<std::size_t, 3>> tris;
  std::vector<Index> source;           // per kept triangle: its element
  std::vector<std::size_t> triangleOf;  // per kept triangle: its index in iso.triangles
  for (std::size_t k = 0; k < iso.triangles.size(); ++k) {
    const auto& t = iso.triangles[k];
    const std::array<std::size_t, 3> w{welded[t[0]], welded[t[1]], welded[t[2]]};
    if (w[0] == w[1] || w[1] == w[2] || w[2] == w[0]) {
      ++result.degenerateTriangles;
      continue;
    }
    auto key = w;
    std::sort(key.begin(), key.end());
    byCorners[key].push_back(tris.size());
    tris.push_back(w);
    source.push_back(k < iso.element.size() ? iso.element[k] : kNoIndex);
    triangleOf.push_back(k);
  }
  auto sameOrientation = [](const std::array<std::size_t, 3>& a, const std::array<std::size_t, 3>& b) {
    for (int r = 0; r < 3; ++r)
      if (a[0] == b[r] && a[1] == b[(r + 1) % 3] && a[2] == b[(r + 2) % 3]) return true;
    return false;
  };
  std::vector<std::uint8_t> dropped(tris.size(), 0);
  for (const auto& [key, list] : byCorners)
    for (std::size_t i = 0; i < list.size(); ++i)
      for (std::size_t j = i + 1; j < list.size() && !dropped[list[i]]; ++j)
        if (!dropped[list[j]] && !sameOrientation(tris[list[i]], tris[list[j]])) {
          dropped[list[i]] = dropped[list[j]] = 1;
          result.degenerateTriangles += 2;
        }
  std::vector<std::vector<std::size_t>> faces;
  std::vector<Index> faceSource;
  std::vector<std::size_t> faceTriangle;
  faces.reserve(tris.size());
  for (std::size_t i = 0; i < tris.size(); ++i)
    if (!dropped[i]) {
      faces.push_back({tris[i][0], tris[i][1], tris[i][2]});
      faceSource.push_back(source[i]);
      faceTriangle.push_back(triangleOf[i]);
    }
  if (faces.empty()) return out;
  if (!PMP::is_polygon_soup_a_polygon_mesh(faces)) PMP::orient_polygon_soup(points, faces);
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, faces, mesh);
  using Face = typename Mesh::Face_index;
  // Faces keep the soup's order (polygon_soup_to_polygon_mesh adds them in order).
  std::vector<Face> range;
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (checked.empty() || checked[faceTriangle[f]]) range.push_back(Face(static_cast<typename Mesh::size_type>(f)));
  std::vector<std::pair<Face, Face>> pairs;
  PMP::self_intersections(range, mesh, std::back_inserter(pairs));
  // CGAL reports a degenerate face f as the pair (f, f), and only so.
  std::vector<std::size_t> crossing;
  for (const auto& [f, g] : pairs) {
    ++(f == g ? result.degenerateTriangles : result.intersectingPairs);
    if (f == g) continue;
    crossing.push_back(faceTriangle[static_cast<std::size_t>(f)]);
    crossing.push_back(faceTriangle[static_cast<std::size_t>(g)]);
    if (result.elementPairs.size() < 100)
      result.elementPairs.push_back({faceSource[static_cast<std::size_t>(f)], faceSource[static_cast<std::size_t>(g)]});
  }
  std::sort(crossing.begin(), crossing.end());
  crossing.erase(std::unique(crossing.begin(), crossing.end()), crossing.end());
  out.crossingTriangles = std::move(crossing);
  return out;
}

// The triangles of `iso` whose rounded bounding boxes meet the box of a
// crossing triangle grown by that triangle's own size on every side: where
// the exact surface has to decide. Empty (= all) when the crossings are too
// many for a quadratic scan to be cheaper than checking everything.
std::vector<std::uint8_t> trianglesNear(const IsoSurface& iso, const std::vector<std::size_t>& crossing) {
  constexpr std::size_t kMaxCrossingTriangles = 256;
  if (crossing.size() > kMaxCrossingTriangles) return {};
  auto box = [&](std::size_t k) {
    std::array<double, 6> b{INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
    for (Index p : iso.triangles[k])
      for (int a = 0; a < 3; ++a) {
        b[a] = std::min(b[a], iso.points[p][a]);
        b[a + 3] = std::max(b[a + 3], iso.points[p][a]);
      }
    return b;
  };
  std::vector<std::array<double, 6>> grown;
  for (std::size_t k : crossing) {
    auto b = box(k);
    const double size = std::max({b[3] - b[0], b[4] - b[1], b[5] - b[2]});
    for (int a = 0; a < 3; ++a) {
      b[a] -= size;
      b[a + 3] += size;
    }
    grown.push_back(b);
  }
  std::vector<std::uint8_t> near(iso.triangles.size(), 0);
  for (std::size_t k = 0; k < iso.triangles.size(); ++k) {
    const auto b = box(k);
    for (const auto& g : grown)
      if (b[0] <= g[3] && g[0] <= b[3] && b[1] <= g[4] && g[1] <= b[4] && b[2] <= g[5] && g[2] <= b[5]) {
        near[k] = 1;
        break;
      }
  }
  return near;
}

// The check on the rounded (written) points.
Check roundedCheck(const IsoSurface& iso) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  Check c = check<Kernel, Vec3>(
      iso, [&](std::size_t i) { return iso.points[i]; },
      [&](std::size_t i) { return Kernel::Point_3(iso.points[i][0], iso.points[i][1], iso.points[i][2]); });
  c.result.roundedCrossings = c.result.intersectingPairs;
  return c;
}

}  // namespace

IsoSurfaceIntersections isoSurfaceSelfIntersections(const IsoSurface& iso) { return roundedCheck(iso).result; }

IsoSurfaceIntersections isoSurfaceSelfIntersections(const IsoSurface& iso, const PairMesh& mesh) {
  // The rounded points first (fast); only when they show crossings does the
  // exact surface decide, and only around them: exact arithmetic on a whole
  // surface of flat cuts takes minutes (80 s on the bundled thin wall for
  // 12 rounded crossings, 2026-12-02), and away from the rounded crossings
  // the rounded points decide, as they do when they show none at all.
  const Check rounded = roundedCheck(iso);
  if (rounded.result.intersectingPairs == 0 || iso.pointNodes.size() != iso.points.size()) return rounded.result;
  const std::vector<std::uint8_t> near = trianglesNear(iso, rounded.crossingTriangles);
  using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
  using Point = Kernel::Point_3;
  const Kernel::FT t(iso.t), u = Kernel::FT(1) - t;
  auto nodePoint = [&](Index n) { return Point(mesh.nodes[n][0], mesh.nodes[n][1], mesh.nodes[n][2]); };
  auto at = [&](Index n) { return n == kNoIndex ? Vec3{NAN, NAN, NAN} : mesh.nodes[n]; };
  IsoSurfaceIntersections exact = check<Kernel, std::pair<Vec3, Vec3>>(
      iso,
      [&](std::size_t i) {  // equal node positions give equal points
        const auto& [s, v] = iso.pointNodes[i];
        if (s == kNoIndex) return std::pair{Vec3{0, 0, 0}, at(v)};
        if (v == kNoIndex) return std::pair{at(s), Vec3{0, 0, 0}};
        return std::pair{at(s), at(v)};
      },
      [&](std::size_t i) {
        const auto& [s, v] = iso.pointNodes[i];
        if (s == kNoIndex) return nodePoint(v);
        if (v == kNoIndex) return nodePoint(s);
        const Point ps = nodePoint(s), pv = nodePoint(v);
        return Point(u * pv.x() + t * ps.x(), u * pv.y() + t * ps.y(), u * pv.z() + t * ps.z());
      },
      near).result;
  // Flat triangles are counted over the whole surface, as by the rounded check.
  exact.degenerateTriangles = rounded.result.degenerateTriangles;
  exact.roundedCrossings = rounded.result.intersectingPairs;
  return exact;
}

}  // namespace cadmedial
