// Small MedialComplex builders shared by the core topology tests.
#pragma once

#include <vector>

#include "cadmedial/polygon_complex.hpp"

namespace cadmedial {

// A complex of Voronoi-facet polygons over the given points, every vertex
// with medial radius `radius`.
inline MedialComplex sheetOf(const std::vector<Vec3>& points, double radius,
                             const std::vector<std::vector<Index>>& polygons) {
  MedialComplex mc;
  for (std::size_t v = 0; v < points.size(); ++v) {
    mc.vertices.push_back(points[v]);
    mc.radius.push_back(radius);
    mc.vertexCell.push_back(Index(v));
    mc.vertexSample.push_back(kNoIndex);
  }
  for (const auto& p : polygons) {
    mc.polygonVertices.insert(mc.polygonVertices.end(), p.begin(), p.end());
    mc.polygonOffsets.push_back(Index(mc.polygonVertices.size()));
    mc.provenance.push_back(PolygonProvenance::DelaunayEdgeFacet);
    mc.provenanceSamples.push_back({0, 1});
  }
  return mc;
}

}  // namespace cadmedial
