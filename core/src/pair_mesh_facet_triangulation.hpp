// Private to the pair-mesh repair: the triangulation of the Voronoi polygons
// of Face-Vertex pyramids.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "cadmedial/pair_mesh.hpp"

namespace cadmedial {

// A Face-Vertex pair of pyramids (apexes a and b, the samples of one interior
// Delaunay edge) over one Voronoi polygon may use any triangulation of the
// polygon: the signed volumes still add up, and the faces shared with the
// neighbours (the polygon's sides coned to a and b) do not change. Built as a
// fan, which is fine while the polygon is convex; once the repair has moved
// its nodes it can fold where another triangulation would not.
class FaceVertexPolygons {
 public:
  // Indexes the element slots of every polygon; valid until elements are
  // added, removed or reordered (re-triangulating keeps the slots).
  explicit FaceVertexPolygons(const PairMesh& mesh);

  // For the polygons of the given elements (others are ignored): picks the
  // triangulation with the fewest elements needing repair, then the largest
  // smallest volume relative to size (dynamic programming over the polygon,
  // O(k^3)), and keeps it when it has fewer bad elements than the current
  // one. Returns the number of polygons re-triangulated.
  std::size_t improve(PairMesh& mesh, const std::vector<std::size_t>& elements) const;

 private:
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> slots_;
};

// Every polygon with an element needing repair, as above.
std::size_t retriangulateFaceVertexPolygons(PairMesh& mesh);

}  // namespace cadmedial
