#include <array>
#include <cstdint>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "cadmedial/cell_sides.hpp"
#include "cadmedial/inner_outer.hpp"
#include "cadmedial/timer.hpp"

namespace cadmedial {

namespace {

Vec3 facetCentroid(const DelaunayVoronoi& dv, const SelectedFacets& sel, Index f) {
  Vec3 c{0, 0, 0};
  for (const Index* it = sel.ringBegin(f); it != sel.ringEnd(f); ++it)
    for (int k = 0; k < 3; ++k) c[k] += dv.circumcenter(*it)[k];
  const double n = sel.ringSize(f);
  return {c[0] / n, c[1] / n, c[2] / n};
}

Vec3 forcedCentroid(const DelaunayVoronoi& dv, const SampleSet& samples, const ForcedTriangle& t) {
  Vec3 c{0, 0, 0};
  int n = 0;
  for (Index s : t.samples)
    if (s != kNoIndex) {
      for (int k = 0; k < 3; ++k) c[k] += samples.points[s][k];
      ++n;
    }
  for (Index v : t.cells)
    if (v != kNoIndex) {
      for (int k = 0; k < 3; ++k) c[k] += dv.circumcenter(v)[k];
      ++n;
    }
  return {c[0] / n, c[1] / n, c[2] / n};
}

}  // namespace

InnerOuterLabels separateInnerOuter(const DelaunayVoronoi& dv, const SampleSet& samples,
                                    const SelectedFacets& selected, const ForcedTriangles& forced,
                                    const MedialParams& params, const InsideOracle& oracle,
                                    const std::vector<std::uint8_t>& cellSide,
                                    const InsideOracle& exactSideNearSurface) {
  Stopwatch watch;
  InnerOuterLabels out;
  const std::size_t nf = selected.size();
  out.facetOuter.assign(nf, 0);
  out.forcedOuter.assign(forced.triangles.size(), 0);

  // Samples whose Voronoi cell's edges the walk may not cross.
  std::vector<std::uint8_t> blocks(samples.size(), 0);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    bool b = false;
    if (params.walkBlocking != WalkBlocking::None && i < samples.isNonConcaveCorner.size())
      b = samples.isNonConcaveCorner[i] != 0;
    if (params.walkBlocking == WalkBlocking::CornersAndConvexEdges && i < samples.onConvexEdge.size())
      b = b || samples.onConvexEdge[i] != 0;
    if (b) blocks[dv.canonicalSample(static_cast<Index>(i))] = 1;
  }

  // Refused crossings are remembered to report whether blocking mattered.
  std::vector<Index> refusedTargets;
  std::vector<Index> stack, thirdSample;
  for (Index seed = 0; seed < nf; ++seed) {
    if (!selected.unbounded[seed]) continue;
    ++out.seeds;
    if (out.facetOuter[seed]) continue;
    ++out.walks;
    out.facetOuter[seed] = 1;
    stack.push_back(seed);
    while (!stack.empty()) {
      const Index f = stack.back();
      stack.pop_back();
      const Index p = selected.edge[f][0], q = selected.edge[f][1];
      const Index* ring = selected.ringBegin(f);
      const Index k = selected.ringSize(f);
      // The third sample x of each Voronoi edge of the ring first, with the
      // table slots of px and qx prefetched: the lookups below are cache
      // misses in a table of millions of facets, and issued together they
      // overlap (the bottle's walk 0.89 -> 0.78 s, min of 3 runs).
      thirdSample.resize(k);
      for (Index t = 0; t < k; ++t) {
        // Consecutive cells share the Delaunay triangle p q x (a Voronoi edge).
        const std::array<Index, 4>& a = dv.cellSamples(ring[t]);
        const std::array<Index, 4>& b = dv.cellSamples(ring[(t + 1) % k]);
        Index x = kNoIndex;
        for (Index s : a) {
          if (s == kNoIndex || s == p || s == q) continue;
          if (s == b[0] || s == b[1] || s == b[2] || s == b[3]) {
            x = s;
            break;
          }
        }
        thirdSample[t] = x;
        if (x != kNoIndex) {
          selected.lookup.prefetch(p, x);
          selected.lookup.prefetch(q, x);
        }
      }
      for (Index t = 0; t < k; ++t) {
        const Index x = thirdSample[t];
        if (x == kNoIndex) continue;  // triangle p q ∞: no other finite edge
        if (!cellSide.empty() &&
            (cellSide[ring[t]] == kCellInside || cellSide[ring[(t + 1) % k]] == kCellInside)) {
          for (Index g : {selected.find(p, x), selected.find(q, x)})
            if (g != kNoIndex && !out.facetOuter[g]) ++out.surfaceCrossingsRefused;
          continue;
        }
        const bool blocked = blocks[p] || blocks[q] || blocks[x];
        for (Index g : {selected.find(p, x), selected.find(q, x)}) {
          if (g == kNoIndex || out.facetOuter[g]) continue;
          if (blocked) {
            ++out.blockedCrossings;
            refusedTargets.push_back(g);
            continue;
          }
          out.facetOuter[g] = 1;
          stack.push_back(g);
        }
      }
    }
  }
  // A facet the walk did not reach but with a Voronoi vertex clearly outside
  // the sampled surface is outer: islands of the outer axis that no walk
  // reaches (cut off by refused crossings, or bounded outer pieces), and the
  // far vertices of nearly cospherical cells that would otherwise hang huge
  // spikes off the inner axis.
  // A facet whose every vertex is outside the reconstruction but within the
  // band is outer when its centroid is outside the exact solid, if the
  // caller has it: the outer axis in a hole a few samples round lies in
  // the band (a 1 mm hole in a 120 mm plate kept seven one-facet islands in
  // the hole, test_small_holes.cpp). Only such facets: with one vertex in
  // the band enough, 6 facets by the knife edge of a wedge of 8° went and
  // left 2 loops, and the lever gained 2 islands.
  if (params.innerNeedsInsideVertices && !cellSide.empty())
    for (Index f = 0; f < nf; ++f) {
      if (out.facetOuter[f]) continue;
      bool allNear = true;
      for (const Index* it = selected.ringBegin(f); it != selected.ringEnd(f); ++it) {
        if (cellSide[*it] == kCellOutside) {
          out.facetOuter[f] = 1;
          ++out.innerFacetsOutsideSurface;
          break;
        }
        allNear = allNear && cellSide[*it] == kCellNearOutside;
      }
      if (!out.facetOuter[f] && allNear && exactSideNearSurface &&
          !exactSideNearSurface(facetCentroid(dv, selected, f))) {
        out.facetOuter[f] = 1;
        ++out.nearFacetsOutsideExactly;
      }
    }
  for (Index f = 0; f < nf; ++f) (out.facetOuter[f] ? out.outerFacets : out.innerFacets)++;
  for (Index g : refusedTargets) out.blockedCrossingsToInner += out.facetOuter[g] ? 0 : 1;

  // Voronoi vertices used by inner / outer fan and corner triangles, so that
  // fills (which hang on no facet) follow the triangles they close.
  std::vector<std::uint8_t> cellOnInner(dv.cellCount(), 0), cellOnOuter(dv.cellCount(), 0);
  for (std::size_t i = 0; i < forced.triangles.size(); ++i) {
    const ForcedTriangle& t = forced.triangles[i];
    if (t.kind == PolygonProvenance::ConvexEdgeFillTriangle) continue;
    const bool attachedOuter = t.attachedFacet != kNoIndex && out.facetOuter[t.attachedFacet];
    for (Index c : t.cells)
      if (c != kNoIndex) (attachedOuter ? cellOnOuter : cellOnInner)[c] = 1;
    if (!attachedOuter) continue;
    out.forcedOuter[i] = 1;
    if (t.kind == PolygonProvenance::CornerTriangle) ++out.outerCornerTriangles;
    else ++out.outerConvexTriangles;
  }
  // A fill s s' v is outer when v only lies on outer triangles: on circular
  // rims the fans at s and s' can meet at a Voronoi vertex of the outer axis.
  for (std::size_t i = 0; i < forced.triangles.size(); ++i) {
    const ForcedTriangle& t = forced.triangles[i];
    if (t.kind != PolygonProvenance::ConvexEdgeFillTriangle) continue;
    const Index v = t.cells[0];
    if (v != kNoIndex && cellOnOuter[v] && !cellOnInner[v]) {
      out.forcedOuter[i] = 1;
      ++out.outerConvexTriangles;
    }
  }
  out.seconds = watch.seconds();

  if (oracle) {
    Stopwatch ow;
    // A polygon with a vertex no inner ball has is not inside, whatever its
    // centroid - a mean of points 1e15 away - hits. The box is padded by
    // 1e-6 of its diagonal: a flat cell's circle centre on a planar face of
    // the box can fall a rounding step outside it.
    const double pad = 1e-6 * samples.bboxDiagonal();
    auto beyondSolid = [&](Index cell) { return beyondSampledSolid(dv, samples, cell, pad); };
    // The oracle's answers in parallel (an exact query costs 10-100 µs;
    // the oracle is safe to call concurrently, medial_params.hpp), the
    // counts after, in order.
    std::vector<std::uint8_t> facetInside(nf, 0), forcedInside(forced.triangles.size(), 0);
    const tbb::blocked_range<Index> facets(0, static_cast<Index>(nf), 256);
    tbb::parallel_for(facets, [&](const tbb::blocked_range<Index>& r) {
      for (Index f = r.begin(); f != r.end(); ++f) {
        if (selected.unbounded[f]) continue;
        bool far = false;
        for (const Index* it = selected.ringBegin(f); it != selected.ringEnd(f) && !far; ++it)
          far = beyondSolid(*it);
        facetInside[f] = !far && oracle(facetCentroid(dv, selected, f));
      }
    });
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, forced.triangles.size(), 256),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i != r.end(); ++i) {
                          bool far = false;
                          for (Index v : forced.triangles[i].cells) far = far || (v != kNoIndex && beyondSolid(v));
                          forcedInside[i] = !far && oracle(forcedCentroid(dv, samples, forced.triangles[i]));
                        }
                      });
    for (Index f = 0; f < nf; ++f) {
      if (selected.unbounded[f]) continue;
      ++out.oracleFacetsChecked;
      const bool inside = facetInside[f] != 0;
      const bool inner = !out.facetOuter[f];
      if (inside != inner) {
        ++out.oracleFacetDisagreements;
        out.oracleInnerOutside += inner ? 1 : 0;
      }
    }
    for (std::size_t i = 0; i < forced.triangles.size(); ++i) {
      ++out.oracleForcedChecked;
      if ((forcedInside[i] != 0) == (out.forcedOuter[i] != 0)) ++out.oracleForcedDisagreements;
    }
    out.oracleSeconds = ow.seconds();
  }
  return out;
}

}  // namespace cadmedial
