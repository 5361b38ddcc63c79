// Thinning of the fringe that the Angle condition keeps around 1-D parts of
// the medial axis (the centre curve of a fillet, the axis of a cylinder, the
// core circle of a torus). See ARCHITECTURE.md "Two contacts".
//
// Why: where the boundary is curved more tightly than the sampling resolves
// (|pq| > 2 r sin θ), the chord pq between two neighbouring samples of one
// smooth surface passes the Angle condition, and its Voronoi facet is kept.
// Those facets reach from the centre curve towards the surface: a fringe of
// fins whose vertices are off the true axis by up to ~0.2 r and have one
// contact instead of two (two-contact share 51 % on a box with every edge
// filleted, 85 % on a torus). A fin vertex v off the curve by d has radius
// r_v ≈ r - d: its ball lies inside the ball of the curve's vertex u
// (|u - v| + r_v ≈ r_u), which is what a true sheet vertex never does
// (along a sheet, r grows slower than distance: by sin(φ/2) for a sheet
// between two faces at angle φ).
//
// How: polygons are removed one at a time by elementary collapses (a
// polygon whose contact with the rest of the complex is one connected arc
// of its boundary, i.e. it hangs on a connected piece: the complex without
// it is homotopy equivalent, so β0, β1, β2 are kept), and only where
//   * it is a Voronoi facet (never a forced convex-edge or corner triangle),
//   * its Delaunay edge pq joins two samples of one smooth surface (the same
//     face, or faces joined by a tangent-continuous edge; not a sharp edge
//     or a corner sample) whose normals are less than 90° apart: a chord,
//     not a pair of opposite contacts,
//   * every vertex that goes with it is dominated, and so is one end of
//     each of its free edges: dominated means some other vertex u at
//     least minReach away has r_u - r_v + slack ≥ cosβ |u - v| (its ball
//     contains v's up to slack and 1 - cosβ of their distance; the fin
//     vertices' balls stick out of the curve's by 0.01-0.06 on a torus of
//     tube radius 10 sampled at h 2.9, hence slack 0.03 h by default).
// The erosion starts at the complex's free edges and stops at undominated
// vertices and at facets that are not chords of one smooth surface (the
// facets across a tube, the sheet between two faces), and never cuts the
// complex apart or opens a loop. What mostly stops it is the candidate
// rule: with the slack, a vertex that has another vertex within about
// slack / (cosβ - growth) is dominated even on a true sheet (a torus: all
// but 92 of 32,427 vertices), so on a true sheet made of such chords (a
// smooth blob's axis near its rim, where the two contacts are less than
// 90° apart) the erosion can trim the part whose balls nest. A dominating
// vertex may itself be removed later, so the removed balls are not
// guaranteed to lie within slack of a kept one; the eval's coverage
// measures what that costs (100 % on every part tried, bundled, public and
// the robustness sweep's). Smooth adjacency is per pair of faces: two faces
// that meet tangentially somewhere and along a sharp edge elsewhere count
// as smooth neighbours everywhere (such a sharp edge's sheet ends in
// forced triangles, which are never removed).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "cadmedial/ball_tree.hpp"
#include "cadmedial/polygon_complex.hpp"
#include "cadmedial/vec3_ops.hpp"

namespace cadmedial {

namespace {

using vec3::cross;
using vec3::dot;
using vec3::sub;

// Area-weighted outward normal of each sample's umbrella (unnormalised).
// Computed here rather than taken from UmbrellaData: its normals are
// unoriented (the Angle condition uses lines), and the chord rule needs the
// side (opposite normals across a tube are two contacts, not a chord).
std::vector<Vec3> sampleNormals(const SampleSet& s) {
  std::vector<Vec3> n(s.size(), Vec3{0, 0, 0});
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    if (!s.triangleOffSurface.empty() && s.triangleOffSurface[t]) continue;
    const auto& tri = s.triangles[t];
    const Vec3 c = cross(sub(s.points[tri[1]], s.points[tri[0]]), sub(s.points[tri[2]], s.points[tri[0]]));
    for (Index i : tri)
      for (int k = 0; k < 3; ++k) n[i][k] += c[k];
  }
  return n;
}

// The faces a sample lies on if it lies on one smooth surface: its face, or
// the two faces of a tangent-continuous edge. Empty on sharp edges and at
// B-rep vertices, where two contacts meet.
struct SmoothFaces {
  std::int32_t a = -1, b = -1;
  bool any() const { return a >= 0; }
};

SmoothFaces smoothFacesOf(const SampleSet& s, Index i) {
  const std::int32_t owner = s.owner[i];
  if (s.kind[i] == SampleKind::Face) return {owner, owner};
  if (s.kind[i] == SampleKind::Edge && owner >= 0 && static_cast<std::size_t>(owner) < s.edges.size()) {
    const EdgeInfo& e = s.edges[owner];
    if (e.kind == EdgeKind::Smooth && e.faceLeft >= 0) return {e.faceLeft, e.faceRight >= 0 ? e.faceRight : e.faceLeft};
  }
  return {};
}

std::uint64_t facePair(std::int32_t f, std::int32_t g) {
  if (f > g) std::swap(f, g);
  return (std::uint64_t(std::uint32_t(f)) << 32) | std::uint32_t(g);
}

// Pairs of faces joined by a tangent-continuous edge.
std::vector<std::uint64_t> smoothFacePairs(const SampleSet& s) {
  std::vector<std::uint64_t> pairs;
  for (const EdgeInfo& e : s.edges)
    if (e.kind == EdgeKind::Smooth && e.faceLeft >= 0 && e.faceRight >= 0) pairs.push_back(facePair(e.faceLeft, e.faceRight));
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace

std::size_t thinFringe(MedialComplex& mc, const SampleSet& samples, const FringeThinningParams& params) {
  const std::size_t nf = mc.polygonCount(), nv = mc.vertices.size();
  if (!(params.cosBeta > 0 && params.cosBeta <= 1) || !(params.slack >= 0) || !(params.minReach > 0))
    throw std::invalid_argument("thinFringe: cosBeta must be in (0, 1], slack >= 0 and minReach > 0");
  if (nf == 0) return 0;

  // Which polygons may go: Voronoi facets of a chord on one smooth surface.
  const std::vector<Vec3> normal = sampleNormals(samples);
  const std::vector<std::uint64_t> smoothPairs = smoothFacePairs(samples);
  auto smoothNeighbours = [&](std::int32_t f, std::int32_t g) {
    return f == g || std::binary_search(smoothPairs.begin(), smoothPairs.end(), facePair(f, g));
  };
  std::vector<std::uint8_t> candidate(nf, 0);
  for (std::size_t p = 0; p < nf; ++p) {
    if (mc.provenance[p] != PolygonProvenance::DelaunayEdgeFacet) continue;
    const Index a = mc.provenanceSamples[p][0], b = mc.provenanceSamples[p][1];
    if (a >= samples.size() || b >= samples.size() || dot(normal[a], normal[b]) <= 0) continue;
    const SmoothFaces fa = smoothFacesOf(samples, a), fb = smoothFacesOf(samples, b);
    if (!fa.any() || !fb.any()) continue;
    candidate[p] = smoothNeighbours(fa.a, fb.a) || smoothNeighbours(fa.a, fb.b) || smoothNeighbours(fa.b, fb.a) ||
                   smoothNeighbours(fa.b, fb.b);
  }

  // Nothing to erode (a part with planar faces only: no chord of one smooth
  // surface): the edges and the ball tree below (0.5 s on a box at 347 k
  // samples) are not needed.
  if (std::find(candidate.begin(), candidate.end(), 1) == candidate.end()) return 0;

  const ComplexEdges edges = buildComplexEdges(mc);
  std::vector<Index> edgeUse(edges.polygonCount);
  std::vector<Index> vertexUse(nv, 0);
  std::vector<Index> vertexOffsets(nv + 1, 0);
  for (Index v : mc.polygonVertices) ++vertexOffsets[v + 1];
  for (std::size_t v = 0; v < nv; ++v) {
    vertexUse[v] = vertexOffsets[v + 1];
    vertexOffsets[v + 1] += vertexOffsets[v];
  }
  std::vector<Index> vertexPolygons(mc.polygonVertices.size());
  {
    std::vector<Index> fill(vertexOffsets.begin(), vertexOffsets.end() - 1);
    for (std::size_t p = 0; p < nf; ++p)
      for (Index k = mc.polygonOffsets[p]; k < mc.polygonOffsets[p + 1]; ++k)
        vertexPolygons[fill[mc.polygonVertices[k]]++] = static_cast<Index>(p);
  }

  // Dominance of a vertex v:
  // r_u - r_v + slack >= cosβ |u - v|  <=>  |u - v| - r_u / cosβ <= (slack - r_v) / cosβ,
  // the smallest gap to balls of radius r_u / cosβ, searched in a BallTree.
  std::vector<BallTree::Ball> balls(nv);
  for (std::size_t v = 0; v < nv; ++v) balls[v] = {mc.vertices[v], mc.radius[v] / params.cosBeta};
  const BallTree tree(std::move(balls));
  // Only candidate polygons are ever checked (the queue holds no other), so
  // only their corners are asked: decided up front, on all cores (115 k of
  // 157 k vertices on the torus at h/4).
  std::vector<std::uint8_t> dominated(nv, 0), asked(nv, 0);
  for (std::size_t p = 0; p < nf; ++p)
    if (candidate[p])
      for (Index k = mc.polygonOffsets[p]; k < mc.polygonOffsets[p + 1]; ++k) asked[mc.polygonVertices[k]] = 1;
  // A vertex's neighbours along the polygons' sides are asked first, by the
  // same inequality over the same balls as the tree's search (so the answer
  // is the same): on a fin the next vertex toward the curve usually
  // dominates, and the search is left for the vertices none of them does.
  auto dominatedByNeighbour = [&](Index v, double limit) {
    auto dominates = [&](Index u) {
      const double d = BallTree::distance(mc.vertices[v], mc.vertices[u]);
      return !(d < params.minReach) && d - mc.radius[u] / params.cosBeta <= limit;
    };
    for (Index j = vertexOffsets[v]; j < vertexOffsets[v + 1]; ++j) {
      const Index p = vertexPolygons[j], b = mc.polygonOffsets[p], n = mc.polygonSize(p);
      for (Index i = 0; i < n; ++i)
        if (mc.polygonVertices[b + i] == v &&
            (dominates(mc.polygonVertices[b + (i + 1) % n]) || dominates(mc.polygonVertices[b + (i + n - 1) % n])))
          return true;
    }
    return false;
  };
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 1024), [&](const auto& r) {
    for (std::size_t v = r.begin(); v != r.end(); ++v) {
      if (!asked[v] || !(mc.radius[v] > 0)) continue;
      const double limit = (params.slack - mc.radius[v]) / params.cosBeta;
      dominated[v] = dominatedByNeighbour(static_cast<Index>(v), limit) ||
                     tree.hasGapAtMost(mc.vertices[v], limit, params.minReach);
    }
  });
  auto isDominated = [&](Index v) { return dominated[v] == 1; };

  std::vector<std::uint8_t> alive(nf, 1);
  // A polygon may collapse if its contact with the rest is one arc of its
  // boundary (cycle v0 e0 v1 e1 ...: exactly one change from attached to
  // free), every vertex that goes with it is dominated, and every free edge
  // has a dominated end (a free edge between two maximal balls, e.g. on the
  // 1-D curve, stays; one from the curve out along a fin goes).
  std::vector<std::uint8_t> attached;
  // Whether each polygon is simple (no repeated corner), decided when first
  // asked: a polygon is checked again after each neighbour's collapse, and
  // the Voronoi facets round a torus's core circle have dozens of corners.
  std::vector<std::int8_t> simple(nf, -1);
  auto isSimple = [&](Index p) {
    if (simple[p] < 0) {
      const Index b = mc.polygonOffsets[p], n = mc.polygonSize(p);
      simple[p] = 1;
      for (Index i = 0; i < n && simple[p]; ++i)
        for (Index j = i + 1; j < n; ++j)
          if (mc.polygonVertices[b + j] == mc.polygonVertices[b + i]) {
            simple[p] = 0;
            break;
          }
    }
    return simple[p] == 1;
  };
  auto collapsible = [&](Index p) {
    const Index b = mc.polygonOffsets[p], n = mc.polygonSize(p);
    if (n < 3 || !isSimple(p)) return false;
    attached.assign(2 * n, 0);
    for (Index i = 0; i < n; ++i) {
      const Index v = mc.polygonVertices[b + i];
      attached[2 * i] = vertexUse[v] >= 2;
      attached[2 * i + 1] = edgeUse[edges.slotEdge[b + i]] >= 2;
    }
    int changes = 0;
    for (Index i = 0; i < 2 * n; ++i) changes += attached[i] && !attached[(i + 1) % (2 * n)];
    if (changes != 1) return false;
    for (Index i = 0; i < n; ++i) {
      const Index v = mc.polygonVertices[b + i], next = mc.polygonVertices[b + (i + 1) % n];
      if (!attached[2 * i] && !isDominated(v)) return false;
      if (!attached[2 * i + 1] && !isDominated(v) && !isDominated(next)) return false;
    }
    return true;
  };

  // A stack: a polygon is checked again right after a neighbour goes, so
  // the erosion runs depth-first from each free edge. Order matters, since
  // a collapse can split a neighbour's contact into two arcs: keeping each
  // polygon in the stack once (checked later, in another order) left 1.7 %
  // of the filleted box's vertices off its exact axis instead of 0.6 %.
  std::vector<Index> queue;
  for (std::size_t p = 0; p < nf; ++p) {
    if (!candidate[p]) continue;
    for (Index k = mc.polygonOffsets[p]; k < mc.polygonOffsets[p + 1]; ++k)
      if (edgeUse[edges.slotEdge[k]] == 1) {
        queue.push_back(static_cast<Index>(p));
        break;
      }
  }
  std::size_t removed = 0;
  while (!queue.empty()) {
    const Index p = queue.back();
    queue.pop_back();
    if (!candidate[p] || !collapsible(p)) continue;
    alive[p] = 0;
    candidate[p] = 0;  // from here on: may still go (alive and a candidate), one read in the loop below
    ++removed;
    for (Index k = mc.polygonOffsets[p]; k < mc.polygonOffsets[p + 1]; ++k) {
      --edgeUse[edges.slotEdge[k]];
      const Index v = mc.polygonVertices[k];
      --vertexUse[v];
      for (Index j = vertexOffsets[v]; j < vertexOffsets[v + 1]; ++j)
        if (candidate[vertexPolygons[j]]) queue.push_back(vertexPolygons[j]);
    }
  }
  if (removed > 0) keepPolygons(mc, alive);
  return removed;
}

}  // namespace cadmedial
