#include "cadmedial/polygon_complex.hpp"
#include "cadmedial/union_find.hpp"

namespace cadmedial {

void segmentSheets(MedialComplex& mc, const ComplexEdges& edges) {
  const std::size_t n = mc.polygonCount();
  UnionFind uf(n);
  for (std::size_t e = 0; e < edges.vertices.size(); ++e)
    if (edges.polygonCount[e] == 2) uf.unite(edges.firstPolygon[e], edges.secondPolygon[e]);
  std::vector<Index> rootSheet(n, kNoIndex);
  mc.sheet.assign(n, kNoIndex);
  Index next = 0;
  for (std::size_t p = 0; p < n; ++p) {
    const Index r = uf.find(static_cast<Index>(p));
    if (rootSheet[r] == kNoIndex) rootSheet[r] = next++;
    mc.sheet[p] = rootSheet[r];
  }
  mc.sheetCount = next;
}

}  // namespace cadmedial
