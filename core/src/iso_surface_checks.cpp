// Self-intersections of an iso-parametric surface (issue #4: "no
// self-intersections", checked with CGAL's own test). The surface is a
// triangle soup over indexed points; CGAL's test wants a polygon mesh, so
// the soup is oriented and made manifold first (non-manifold vertices are
// duplicated by CGAL's soup repair, which can only add reported pairs of
// faces touching at such a vertex, never hide a crossing).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <iterator>
#include <map>

#include "cadmedial/pair_mesh.hpp"

namespace cadmedial {

namespace PMP = CGAL::Polygon_mesh_processing;

IsoSurfaceIntersections isoSurfaceSelfIntersections(const IsoSurface& iso) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  IsoSurfaceIntersections result;
  if (iso.triangles.empty()) return result;
  // Flat elements (cospherical samples give coincident Voronoi nodes) cut
  // into triangles whose corners coincide in space under different indices:
  // weld equal positions, drop triangles that collapse, and drop pairs of
  // opposite copies of one triangle (the two faces of a zero-thickness cut).
  // What is left touches only where it shares vertices, or truly crosses.
  std::map<Vec3, std::size_t> weldedIndex;
  std::vector<std::size_t> welded(iso.points.size());
  std::vector<Kernel::Point_3> points;
  for (std::size_t i = 0; i < iso.points.size(); ++i) {
    auto [it, fresh] = weldedIndex.emplace(iso.points[i], points.size());
    if (fresh) points.emplace_back(iso.points[i][0], iso.points[i][1], iso.points[i][2]);
    welded[i] = it->second;
  }
  std::map<std::array<std::size_t, 3>, std::vector<std::size_t>> byCorners;  // sorted corners -> faces
  std::vector<std::array<std::size_t, 3>> tris;
  for (const auto& t : iso.triangles) {
    const std::array<std::size_t, 3> w{welded[t[0]], welded[t[1]], welded[t[2]]};
    if (w[0] == w[1] || w[1] == w[2] || w[2] == w[0]) {
      ++result.degenerateTriangles;
      continue;
    }
    auto key = w;
    std::sort(key.begin(), key.end());
    byCorners[key].push_back(tris.size());
    tris.push_back(w);
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
  faces.reserve(tris.size());
  for (std::size_t i = 0; i < tris.size(); ++i)
    if (!dropped[i]) faces.push_back({tris[i][0], tris[i][1], tris[i][2]});
  if (faces.empty()) return result;
  if (!PMP::is_polygon_soup_a_polygon_mesh(faces)) PMP::orient_polygon_soup(points, faces);
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, faces, mesh);
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
  PMP::self_intersections(mesh, std::back_inserter(pairs));
  // CGAL reports a degenerate face f as the pair (f, f), and only so.
  for (const auto& [f, g] : pairs) ++(f == g ? result.degenerateTriangles : result.intersectingPairs);
  return result;
}

}  // namespace cadmedial
