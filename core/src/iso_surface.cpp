// Iso-parametric surfaces of the pair-mesh (seed 003 §4.2). Every element is
// cut by the plane-like surface where the interim edges reach parameter t;
// the cuts of neighbouring elements share their interim nodes, so the result
// is a closed triangle mesh between the medial side (t = 0) and the boundary
// (t = 1).
#include <unordered_map>

#include "cadmedial/edge_table.hpp"
#include "cadmedial/pair_mesh.hpp"

namespace cadmedial {

IsoSurface isoSurface(const PairMesh& m, double t) {
  IsoSurface out;
  out.t = t;
  const bool atBoundary = t >= 1.0, atMedial = t <= 0.0;
  // Node of interim edge (s, v); merged per sample at t = 1 and per Voronoi
  // node at t = 0, where those nodes coincide.
  PairTable nodeOf;
  nodeOf.reserve(m.size());
  std::unordered_map<Index, Index> single;
  auto node = [&](Index s, Index v) -> Index {
    if (atBoundary || atMedial) {
      const Index key = atBoundary ? s : v;
      auto [it, fresh] = single.emplace(key, static_cast<Index>(out.points.size()));
      if (fresh) {
        out.points.push_back(m.nodes[key]);
        out.pointNodes.push_back(atBoundary ? std::array<Index, 2>{s, kNoIndex} : std::array<Index, 2>{kNoIndex, v});
      }
      return it->second;
    }
    const Index id = nodeOf.insert(s, v, static_cast<Index>(out.points.size()));
    if (id == out.points.size()) {
      const Vec3 &ps = m.nodes[s], &pv = m.nodes[v];
      out.points.push_back({(1 - t) * pv[0] + t * ps[0], (1 - t) * pv[1] + t * ps[1], (1 - t) * pv[2] + t * ps[2]});
      out.pointNodes.push_back({s, v});
    }
    return id;
  };
  Index current = 0;
  auto emit = [&](Index a, Index b, Index c) {
    if (a == b || b == c || c == a) return;
    out.triangles.push_back({a, b, c});
    out.element.push_back(current);
  };
  for (std::size_t i = 0; i < m.size(); ++i) {
    current = static_cast<Index>(i);
    const auto& q = m.tets[i];
    switch (m.type[i]) {
      case PairElementType::FaceVertex:  // (a, c0, ci, cj): the polygon, facing a
        emit(node(q[0], q[1]), node(q[0], q[3]), node(q[0], q[2]));
        break;
      case PairElementType::EdgeEdge: {  // (a, b, ci, cj): the quadrilateral, facing ab
        const Index ai = node(q[0], q[2]), bi = node(q[1], q[2]), bj = node(q[1], q[3]), aj = node(q[0], q[3]);
        emit(ai, bi, bj);
        emit(ai, bj, aj);
        break;
      }
      case PairElementType::VertexFace:  // (c, x, y, z): the triangle, like xyz
        emit(node(q[1], q[0]), node(q[2], q[0]), node(q[3], q[0]));
        break;
    }
  }
  return out;
}

}  // namespace cadmedial
