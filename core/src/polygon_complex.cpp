#include "cadmedial/polygon_complex.hpp"

#include <algorithm>
#include <utility>

#include "cadmedial/unique_edges.hpp"

namespace cadmedial {

MedialComplex buildInnerComplex(const DelaunayVoronoi& dv, const SampleSet& samples, const SelectedFacets& selected,
                                const ForcedTriangles& forced, const InnerOuterLabels& labels) {
  MedialComplex mc;
  std::vector<Index> cellVertex(dv.cellCount(), kNoIndex);
  std::vector<Index> sampleVertex(samples.size(), kNoIndex);
  // Upper bounds, reserved so that the arrays never grow by copies (pages
  // reserved and never written cost nothing; on the bottle, growing them
  // was a few per cent of the core in page faults and copies).
  const std::size_t maxPolygons = selected.size() + forced.triangles.size();
  const std::size_t maxVertices = std::min<std::size_t>(dv.cellCount() + samples.size(),
                                                        selected.ringCells.size() + 3 * forced.triangles.size());
  mc.vertices.reserve(maxVertices);
  mc.radius.reserve(maxVertices);
  mc.vertexCell.reserve(maxVertices);
  mc.vertexSample.reserve(maxVertices);
  mc.polygonOffsets.reserve(maxPolygons + 1);
  mc.polygonVertices.reserve(selected.ringCells.size() + 3 * forced.triangles.size());
  mc.provenance.reserve(maxPolygons);
  mc.provenanceSamples.reserve(maxPolygons);
  auto cellV = [&](Index c) {
    if (cellVertex[c] == kNoIndex) {
      cellVertex[c] = static_cast<Index>(mc.vertices.size());
      mc.vertices.push_back(dv.circumcenter(c));
      mc.radius.push_back(dv.circumradius(c));
      mc.vertexCell.push_back(c);
      mc.vertexSample.push_back(kNoIndex);
    }
    return cellVertex[c];
  };
  auto sampleV = [&](Index s) {
    if (sampleVertex[s] == kNoIndex) {
      sampleVertex[s] = static_cast<Index>(mc.vertices.size());
      mc.vertices.push_back(samples.points[s]);
      mc.radius.push_back(0.0);
      mc.vertexCell.push_back(kNoIndex);
      mc.vertexSample.push_back(s);
    }
    return sampleVertex[s];
  };
  auto close = [&](PolygonProvenance kind, Index a, Index b) {
    mc.polygonOffsets.push_back(static_cast<Index>(mc.polygonVertices.size()));
    mc.provenance.push_back(kind);
    mc.provenanceSamples.push_back({a, b});
  };

  for (Index f = 0; f < selected.size(); ++f) {
    if (selected.unbounded[f] || labels.facetOuter[f]) continue;
    for (const Index* it = selected.ringBegin(f); it != selected.ringEnd(f); ++it)
      mc.polygonVertices.push_back(cellV(*it));
    close(PolygonProvenance::DelaunayEdgeFacet, selected.edge[f][0], selected.edge[f][1]);
  }
  for (std::size_t i = 0; i < forced.triangles.size(); ++i) {
    if (labels.forcedOuter[i]) continue;
    const ForcedTriangle& t = forced.triangles[i];
    if (t.kind == PolygonProvenance::ConvexEdgeFillTriangle) {
      mc.polygonVertices.push_back(sampleV(t.samples[0]));
      mc.polygonVertices.push_back(sampleV(t.samples[1]));
      mc.polygonVertices.push_back(cellV(t.cells[0]));
      close(t.kind, t.samples[0], t.samples[1]);
    } else {
      mc.polygonVertices.push_back(sampleV(t.samples[0]));
      mc.polygonVertices.push_back(cellV(t.cells[0]));
      mc.polygonVertices.push_back(cellV(t.cells[1]));
      close(t.kind, t.samples[0], kNoIndex);
    }
  }
  mc.sheet.assign(mc.polygonCount(), kNoIndex);
  return mc;
}

void keepPolygons(MedialComplex& mc, const std::vector<std::uint8_t>& keep) {
  MedialComplex out;
  std::vector<Index> newIndex(mc.vertices.size(), kNoIndex);
  // At most what there is (see buildInnerComplex).
  out.vertices.reserve(mc.vertices.size());
  out.radius.reserve(mc.vertices.size());
  out.vertexCell.reserve(mc.vertices.size());
  out.vertexSample.reserve(mc.vertices.size());
  out.polygonOffsets.reserve(mc.polygonOffsets.size());
  out.polygonVertices.reserve(mc.polygonVertices.size());
  out.provenance.reserve(mc.provenance.size());
  out.provenanceSamples.reserve(mc.provenanceSamples.size());
  for (std::size_t p = 0; p < mc.polygonCount(); ++p) {
    if (!keep[p]) continue;
    for (Index k = mc.polygonOffsets[p]; k < mc.polygonOffsets[p + 1]; ++k) {
      const Index v = mc.polygonVertices[k];
      if (newIndex[v] == kNoIndex) {
        newIndex[v] = static_cast<Index>(out.vertices.size());
        out.vertices.push_back(mc.vertices[v]);
        out.radius.push_back(mc.radius[v]);
        out.vertexCell.push_back(mc.vertexCell[v]);
        out.vertexSample.push_back(mc.vertexSample[v]);
      }
      out.polygonVertices.push_back(newIndex[v]);
    }
    out.polygonOffsets.push_back(static_cast<Index>(out.polygonVertices.size()));
    out.provenance.push_back(mc.provenance[p]);
    out.provenanceSamples.push_back(mc.provenanceSamples[p]);
  }
  out.sheet.assign(out.polygonCount(), kNoIndex);
  out.weldedCells = std::move(mc.weldedCells);
  mc = std::move(out);
}

ComplexEdges buildComplexEdges(const MedialComplex& mc) {
  std::vector<std::array<Index, 2>> sides(mc.polygonVertices.size());
  for (std::size_t p = 0; p < mc.polygonCount(); ++p) {
    const Index b = mc.polygonOffsets[p], e = mc.polygonOffsets[p + 1];
    for (Index k = b; k < e; ++k) sides[k] = {mc.polygonVertices[k], mc.polygonVertices[k + 1 < e ? k + 1 : b]};
  }
  UniqueEdges unique = findUniqueEdges(mc.vertices.size(), sides);
  ComplexEdges ce;
  ce.vertices = std::move(unique.edges);
  ce.slotEdge = std::move(unique.useEdge);
  const std::size_t ne = ce.vertices.size();
  ce.polygonCount.assign(ne, 0);
  ce.firstPolygon.assign(ne, kNoIndex);
  ce.secondPolygon.assign(ne, kNoIndex);
  for (std::size_t p = 0; p < mc.polygonCount(); ++p)
    for (Index k = mc.polygonOffsets[p]; k < mc.polygonOffsets[p + 1]; ++k) {
      const Index id = ce.slotEdge[k];
      Index& count = ce.polygonCount[id];
      if (count == 0) ce.firstPolygon[id] = static_cast<Index>(p);
      else if (count == 1) ce.secondPolygon[id] = static_cast<Index>(p);
      ++count;
    }
  for (Index c : ce.polygonCount) {
    if (c == 1) ++ce.borderEdges;
    else if (c == 2) ++ce.manifoldEdges;
    else ++ce.junctionEdges;
  }
  return ce;
}

}  // namespace cadmedial
