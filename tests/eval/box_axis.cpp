#include "box_axis.hpp"

#include <algorithm>
#include <functional>
#include <map>

namespace cadmedial::test {

namespace {

// A planar piece as rows k = 0..rows of lattice points m in [lo(k), hi(k)],
// mapped to integer lattice coordinates; consecutive rows are zipped into
// triangles by increasing m (rows are parallel and m is aligned across them).
struct Piece {
  int rows;
  std::function<int(int)> lo, hi;
  std::function<std::array<int, 3>(int m, int k)> at;
};

}  // namespace

MedialMesh exactBoxAxis(int n) {
  const double h = 10.0 / n;                 // lattice step
  const int A = 4 * n, B = 3 * n, C = 2 * n;  // 40, 30, 20 in lattice units
  std::vector<Piece> pieces;
  pieces.push_back({B - 2 * n, [n](int) { return n; }, [=](int) { return A - n; },
                    [n](int m, int k) { return std::array<int, 3>{m, n + k, n}; }});
  for (int sy : {0, 1})
    for (int sz : {0, 1})
      pieces.push_back({n, [](int k) { return k; }, [=](int k) { return A - k; }, [=](int m, int k) {
                          return std::array<int, 3>{m, sy ? B - k : k, sz ? C - k : k};
                        }});
  for (int sx : {0, 1})
    for (int sz : {0, 1})
      pieces.push_back({n, [](int k) { return k; }, [=](int k) { return B - k; }, [=](int m, int k) {
                          return std::array<int, 3>{sx ? A - k : k, m, sz ? C - k : k};
                        }});
  for (int sx : {0, 1})
    for (int sy : {0, 1})
      pieces.push_back({n, [](int k) { return k; }, [=](int k) { return C - k; }, [=](int m, int k) {
                          return std::array<int, 3>{sx ? A - k : k, sy ? B - k : k, m};
                        }});

  MedialMesh mesh;
  std::map<std::array<int, 3>, std::uint32_t> index;
  auto vertex = [&](const std::array<int, 3>& q) {
    const auto it = index.find(q);
    if (it != index.end()) return it->second;
    const int r = std::min({q[0], A - q[0], q[1], B - q[1], q[2], C - q[2]});
    const std::uint32_t id = mesh.addVertex({q[0] * h, q[1] * h, q[2] * h}, r * h);
    index.emplace(q, id);
    return id;
  };
  for (std::size_t s = 0; s < pieces.size(); ++s) {
    const Piece& p = pieces[s];
    for (int k = 0; k < p.rows; ++k) {
      int i = p.lo(k), j = p.lo(k + 1);
      const int iEnd = p.hi(k), jEnd = p.hi(k + 1);
      while (i < iEnd || j < jEnd) {
        const bool advanceBottom = i < iEnd && (j == jEnd || i + 1 <= j + 1);
        if (advanceBottom) {
          mesh.addPolygon({vertex(p.at(i, k)), vertex(p.at(i + 1, k)), vertex(p.at(j, k + 1))}, int(s));
          ++i;
        } else {
          mesh.addPolygon({vertex(p.at(i, k)), vertex(p.at(j + 1, k + 1)), vertex(p.at(j, k + 1))}, int(s));
          ++j;
        }
      }
    }
  }
  return mesh;
}

MedialMesh scaledRadii(MedialMesh mesh, double factor) {
  for (double& r : mesh.radius) r *= factor;
  return mesh;
}

MedialMesh shrunkToward(MedialMesh mesh, const std::array<double, 3>& centre, double factor) {
  for (auto& v : mesh.vertices)
    for (int k = 0; k < 3; ++k) v[k] = centre[k] + factor * (v[k] - centre[k]);
  return mesh;
}

MedialMesh translated(MedialMesh mesh, const std::array<double, 3>& offset) {
  for (auto& v : mesh.vertices)
    for (int k = 0; k < 3; ++k) v[k] += offset[k];
  return mesh;
}

MedialMesh withoutSheet(const MedialMesh& mesh, int sheet) {
  MedialMesh out;
  out.vertices = mesh.vertices;
  out.radius = mesh.radius;
  for (std::size_t i = 0; i < mesh.polygonCount(); ++i) {
    if (mesh.sheet[i] == sheet) continue;
    out.addPolygon({mesh.polygonVertices.begin() + mesh.polygonOffsets[i],
                    mesh.polygonVertices.begin() + mesh.polygonOffsets[i + 1]},
                   mesh.sheet[i], mesh.provenance[i]);
  }
  return out;
}

}  // namespace cadmedial::test
