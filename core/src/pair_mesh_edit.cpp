#include "pair_mesh_edit.hpp"

#include <algorithm>

namespace cadmedial {

namespace {

// Keeps the entries i with drop[i] == 0 of every parallel vector, in order;
// returns each kept entry's new index (kNoIndex for the dropped ones).
template <class... Vectors>
std::vector<Index> keepUndropped(const std::vector<std::uint8_t>& drop, Vectors&... vectors) {
  std::vector<Index> renumber(drop.size(), kNoIndex);
  Index next = 0;
  for (std::size_t i = 0; i < drop.size(); ++i) {
    if (drop[i]) continue;
    renumber[i] = next;
    ((vectors[next] = vectors[i]), ...);
    ++next;
  }
  (vectors.resize(next), ...);
  return renumber;
}

}  // namespace

void removeElements(PairMesh& m, const std::vector<std::uint8_t>& drop, std::vector<std::uint8_t>* perElement) {
  if (perElement)
    keepUndropped(drop, m.tets, m.type, m.medialSimplex, m.boundarySimplex, m.onSheets, *perElement);
  else
    keepUndropped(drop, m.tets, m.type, m.medialSimplex, m.boundarySimplex, m.onSheets);
}

void removeNodes(PairMesh& m, const std::vector<std::uint8_t>& drop) {
  const std::vector<Index> renumber = keepUndropped(drop, m.nodes, m.nodeCell, m.boundaryNode);
  for (auto& t : m.tets)
    for (Index& v : t) v = renumber[v];
}

void recountElements(PairMesh& m) {
  PairMeshCounts& k = m.counts;
  k.faceVertex = k.edgeEdge = k.vertexFace = 0;
  m.boundaryTriangles.clear();
  for (std::size_t i = 0; i < m.size(); ++i) {
    switch (m.type[i]) {
      case PairElementType::FaceVertex: ++k.faceVertex; break;
      case PairElementType::EdgeEdge: ++k.edgeEdge; break;
      case PairElementType::VertexFace:
        ++k.vertexFace;
        m.boundaryTriangles.push_back({m.tets[i][1], m.tets[i][2], m.tets[i][3]});
        break;
    }
  }
  k.boundaryTriangles = m.boundaryTriangles.size();
}

std::size_t splitNodeCount(const PairMesh& m) {
  return static_cast<std::size_t>(
      std::count(m.boundaryNode.begin() + static_cast<std::ptrdiff_t>(m.sampleNodes), m.boundaryNode.end(), 1));
}

}  // namespace cadmedial
