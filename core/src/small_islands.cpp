#include <algorithm>
#include <array>
#include <optional>

#include "cadmedial/ball_tree.hpp"
#include "cadmedial/polygon_complex.hpp"
#include "cadmedial/union_find.hpp"

namespace cadmedial {

VertexComponents vertexComponents(const MedialComplex& mc) {
  const std::size_t nv = mc.vertices.size(), nf = mc.polygonCount();
  UnionFind uf(nv);
  for (std::size_t p = 0; p < nf; ++p)
    for (Index k = mc.polygonOffsets[p] + 1; k < mc.polygonOffsets[p + 1]; ++k)
      uf.unite(mc.polygonVertices[mc.polygonOffsets[p]], mc.polygonVertices[k]);
  // Components are numbered in the order of their roots' vertex ids (a root
  // is its own root), so that "the first component with the most polygons"
  // is the one it was when the rules kept per-vertex arrays indexed by root.
  VertexComponents comps;
  comps.ofVertex.resize(nv);
  for (std::size_t v = 0; v < nv; ++v)
    if (uf.find(static_cast<Index>(v)) == v) comps.ofVertex[v] = comps.count++;
  for (std::size_t v = 0; v < nv; ++v) comps.ofVertex[v] = comps.ofVertex[uf.find(static_cast<Index>(v))];
  // The component with the most polygons is never dropped (not the one with
  // the largest ball: the bottle's whole wall axis has r <= 0.38 < 0.25 h,
  // and its largest ball sat on a 4-polygon island).
  std::vector<Index> polygonsOf(comps.count, 0);
  for (std::size_t p = 0; p < nf; ++p) ++polygonsOf[comps.ofPolygon(mc, p)];
  comps.largest = static_cast<Index>(std::max_element(polygonsOf.begin(), polygonsOf.end()) - polygonsOf.begin());
  return comps;
}

namespace {

// The components of `mc`: those in *shared if it holds them, else computed
// (and kept there for the next rule).
const VertexComponents& componentsOf(const MedialComplex& mc, std::optional<VertexComponents>* shared,
                                     std::optional<VertexComponents>& local) {
  std::optional<VertexComponents>& slot = shared ? *shared : local;
  if (!slot) slot.emplace(vertexComponents(mc));
  return *slot;
}

// Per component: 1 if it has a polygon whose provenance satisfies `wanted`.
template <typename Wanted>
std::vector<std::uint8_t> componentsWithPolygon(const MedialComplex& mc, const VertexComponents& comps, Wanted wanted) {
  std::vector<std::uint8_t> flag(comps.count, 0);
  for (std::size_t p = 0; p < mc.polygonCount(); ++p)
    if (wanted(mc.provenance[p])) flag[comps.ofPolygon(mc, p)] = 1;
  return flag;
}

// Removes the polygons of the components with drop[c] != 0 and the vertices
// no polygon uses any more; returns how many components. The components
// change with the complex, so *shared is emptied when something goes.
std::size_t removeComponents(MedialComplex& mc, const VertexComponents& comps, const std::vector<std::uint8_t>& drop,
                             std::size_t* polygonsRemoved, std::optional<VertexComponents>* shared) {
  if (polygonsRemoved) *polygonsRemoved = 0;
  const std::size_t islands = static_cast<std::size_t>(std::count(drop.begin(), drop.end(), 1));
  if (islands == 0) return 0;
  const std::size_t nf = mc.polygonCount();
  std::vector<std::uint8_t> keep(nf, 1);
  for (std::size_t p = 0; p < nf; ++p)
    if (drop[comps.ofPolygon(mc, p)]) {
      keep[p] = 0;
      if (polygonsRemoved) ++*polygonsRemoved;
    }
  keepPolygons(mc, keep);  // invalidates comps if it is *shared's
  if (shared) shared->reset();
  return islands;
}

}  // namespace

// Why: the inner medial axis of a connected solid is connected (it is
// homotopy equivalent to the solid), so every component but one is an
// artefact. Those we see on CAD parts hang on features far thinner than the
// sample spacing h, e.g. the zero-angle cusp where a concave cylinder meets a
// plane tangentially (lever: seven islands of ≤ 72 polygons, radii ≤ 1.9
// with h = 8.9): the convex-edge completion attaches sheets to the cusp's
// edge samples that the sampling cannot join to the rest. A component all of
// whose balls are below a fraction of h is dropped; a component with any
// larger ball is kept, so a real piece of axis cut off by a coarse region is
// reported (β0) rather than hidden, and the largest component is never
// dropped (a thin part whose whole axis is small stays).
// A component with a forced triangle (convex-edge or corner completion) is
// kept too: it is the only attachment of its edge or corner, and dropping
// those cost the lever 0.8 % of convex-edge length, 2 of 54 corners and
// 0.05 % coverage (measured with scripts/eval_table.py --public).
std::size_t dropSubResolutionIslands(MedialComplex& mc, double minRadius, std::size_t* polygonsRemoved,
                                     std::optional<VertexComponents>* shared) {
  if (polygonsRemoved) *polygonsRemoved = 0;
  const std::size_t nv = mc.vertices.size();
  if (nv == 0 || mc.polygonCount() == 0) return 0;
  std::optional<VertexComponents> local;
  const VertexComponents& comps = componentsOf(mc, shared, local);
  std::vector<double> maxRadius(comps.count, -1.0);
  for (std::size_t v = 0; v < nv; ++v) {
    double& m = maxRadius[comps.ofVertex[v]];
    m = std::max(m, mc.radius[v]);
  }
  const std::vector<std::uint8_t> attached =
      componentsWithPolygon(mc, comps, [](PolygonProvenance p) { return p != PolygonProvenance::DelaunayEdgeFacet; });
  std::vector<std::uint8_t> drop(comps.count, 0);
  for (Index c = 0; c < comps.count; ++c) drop[c] = c != comps.largest && !attached[c] && maxRadius[c] < minRadius;
  return removeComponents(mc, comps, drop, polygonsRemoved, shared);
}

// Why: samples on a sphere are cospherical, so every Delaunay cell of four of
// them has the sphere's centre as circumcenter, and the Voronoi facet between
// two of them can have all its vertices there: a polygon of zero size. When
// no other inner polygon uses those cells, it is a component of its own
// (a box with all edges filleted: its corner spheres gave β0 = 2). Such a
// component is one point, so it adds nothing to the axis but a wrong β0.
std::size_t dropPointIslands(MedialComplex& mc, double tolerance, std::size_t* polygonsRemoved,
                             std::optional<VertexComponents>* shared) {
  if (polygonsRemoved) *polygonsRemoved = 0;
  const std::size_t nv = mc.vertices.size();
  if (nv == 0 || mc.polygonCount() == 0) return 0;
  std::optional<VertexComponents> local;
  const VertexComponents& comps = componentsOf(mc, shared, local);
  std::vector<std::array<double, 6>> box(comps.count, {1e300, 1e300, 1e300, -1e300, -1e300, -1e300});
  for (std::size_t v = 0; v < nv; ++v) {
    auto& b = box[comps.ofVertex[v]];
    for (int k = 0; k < 3; ++k) {
      b[k] = std::min(b[k], mc.vertices[v][k]);
      b[k + 3] = std::max(b[k + 3], mc.vertices[v][k]);
    }
  }
  std::vector<std::uint8_t> drop(comps.count, 0);
  for (Index c = 0; c < comps.count; ++c) {
    const auto& b = box[c];
    drop[c] = c != comps.largest && std::max({b[3] - b[0], b[4] - b[1], b[5] - b[2]}) <= tolerance;
  }
  return removeComponents(mc, comps, drop, polygonsRemoved, shared);
}

// Why: a convex-edge or corner triangle completes the axis from a feature to
// the sheet that the Angle and Ratio conditions kept there. Where they
// pruned that sheet (a weak one: the ridge between two bores of NIST CTC-01
// flattens to tangency at its end, so the Delaunay edges across it are far
// shorter than their balls), the completion is left with nothing to
// complete: a component of forced triangles alone, a few millimetres wide,
// off the rest of the axis (CTC-01: 15 of its 18 extra components). Such a
// component is dropped, never the largest one; the feature points it held
// are the pruned sheet's, which the filter dropped on purpose.
std::size_t dropForcedOnlyIslands(MedialComplex& mc, std::size_t* polygonsRemoved,
                                  std::optional<VertexComponents>* shared) {
  if (polygonsRemoved) *polygonsRemoved = 0;
  const std::size_t nv = mc.vertices.size();
  if (nv == 0 || mc.polygonCount() == 0) return 0;
  std::optional<VertexComponents> local;
  const VertexComponents& comps = componentsOf(mc, shared, local);
  const std::vector<std::uint8_t> hasFacet =
      componentsWithPolygon(mc, comps, [](PolygonProvenance p) { return p == PolygonProvenance::DelaunayEdgeFacet; });
  std::vector<std::uint8_t> drop(comps.count, 0);
  for (Index c = 0; c < comps.count; ++c) drop[c] = c != comps.largest && !hasFacet[c];
  return removeComponents(mc, comps, drop, polygonsRemoved, shared);
}

// Why: an island whose every ball (nearly) nests in a ball of the main axis
// adds (almost) nothing to the union of balls, the shape the axis stands
// for, and a connected solid has a connected axis, so it is no piece of
// axis that the sampling cut off (those have balls of their own) but a
// facet the filter kept where it dropped its neighbours: box_fillet_variable's
// one triangle at a fillet corner (r up to 3.3, h 1.95; its balls stick out
// of the nearest main ball by 0.004, 0.003 and 0.21), a 3-vertex facet of
// NIST CTC-01 (r 19.5, h 9.9, out by <= 0.05); coverage stayed 100 % on
// both. "Nearly" is the fringe thinning's dominance, with its slack:
// r_u - r_v + slack >= cosBeta |u - v| for some vertex u of the component
// with the most polygons, which lets v's ball reach out of u's by up to
// (1 - cosBeta) |u - v| + slack. Islands with a forced triangle stay (they
// hold a convex edge's or corner's attachment).
std::size_t dropNestedIslands(MedialComplex& mc, double cosBeta, double slack, std::size_t* polygonsRemoved,
                              std::optional<VertexComponents>* shared) {
  if (polygonsRemoved) *polygonsRemoved = 0;
  const std::size_t nv = mc.vertices.size();
  if (nv == 0 || mc.polygonCount() == 0 || !(cosBeta > 0)) return 0;
  std::optional<VertexComponents> local;
  const VertexComponents& comps = componentsOf(mc, shared, local);
  const std::vector<std::uint8_t> attached =
      componentsWithPolygon(mc, comps, [](PolygonProvenance p) { return p != PolygonProvenance::DelaunayEdgeFacet; });
  std::vector<std::uint8_t> drop(comps.count, 0);
  bool anyCandidate = false;
  for (Index c = 0; c < comps.count; ++c) {
    drop[c] = c != comps.largest && !attached[c];
    anyCandidate = anyCandidate || drop[c];
  }
  if (!anyCandidate) return 0;  // no tree over the main axis (1.3 M vertices on the bottle)
  // r_u - r_v + slack >= cosBeta |u - v|  <=>  |u - v| - r_u / cosBeta <= (slack - r_v) / cosBeta.
  std::vector<BallTree::Ball> balls;
  for (std::size_t v = 0; v < nv; ++v)
    if (comps.ofVertex[v] == comps.largest) balls.push_back({mc.vertices[v], mc.radius[v] / cosBeta});
  const BallTree mainAxis(std::move(balls));
  for (std::size_t v = 0; v < nv; ++v) {
    const Index c = comps.ofVertex[v];
    if (!drop[c]) continue;
    const double limit = (slack - mc.radius[v]) / cosBeta;
    if (!mainAxis.hasGapAtMost(mc.vertices[v], limit)) drop[c] = 0;
  }
  return removeComponents(mc, comps, drop, polygonsRemoved, shared);
}

}  // namespace cadmedial
