#include "ply_writers.hpp"

#include <iomanip>
#include <vector>

namespace cadmedial {

void writeSamplesPly(std::ostream& out, const SampleSet& s) {
  std::vector<std::uint8_t> role(s.size(), 0);
  for (const Triplet& t : s.triplets) {
    role[t.s] = 1;
    role[t.sLeft] = role[t.sRight] = 2;
  }
  out << "ply\nformat ascii 1.0\ncomment cadmedial samples\n"
      << "element vertex " << s.size() << "\n"
      << "property double x\nproperty double y\nproperty double z\n"
      << "property uchar kind\nproperty int owner\nproperty uchar convex\nproperty uchar nonconcave\n"
      << "property uchar triplet_role\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "element edge " << 2 * s.triplets.size() << "\nproperty int vertex1\nproperty int vertex2\n"
      << "end_header\n";
  out << std::setprecision(17);
  static const int colours[3][3] = {{160, 160, 160}, {220, 40, 40}, {40, 40, 220}};
  for (std::size_t i = 0; i < s.size(); ++i) {
    const int k = static_cast<int>(s.kind[i]);
    const auto& c = role[i] == 2 ? std::array<int, 3>{40, 170, 40}
                                 : std::array<int, 3>{colours[k][0], colours[k][1], colours[k][2]};
    out << s.points[i][0] << ' ' << s.points[i][1] << ' ' << s.points[i][2] << ' ' << k << ' ' << s.owner[i] << ' '
        << int(s.onConvexEdge[i]) << ' ' << int(s.isNonConcaveCorner[i]) << ' ' << int(role[i]) << ' ' << c[0]
        << ' ' << c[1] << ' ' << c[2] << '\n';
  }
  for (const Triplet& t : s.triplets) out << t.s << ' ' << t.sLeft << '\n' << t.s << ' ' << t.sRight << '\n';
}

void writeBoundaryMeshPly(std::ostream& out, const SampleSet& s) {
  out << "ply\nformat ascii 1.0\ncomment cadmedial stitched boundary reconstruction\n"
      << "element vertex " << s.size() << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "element face " << s.triangles.size() << "\nproperty list uchar int vertex_indices\nproperty int face_id\n"
      << "end_header\n";
  out << std::setprecision(17);
  for (const auto& p : s.points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    out << "3 " << s.triangles[t][0] << ' ' << s.triangles[t][1] << ' ' << s.triangles[t][2] << ' '
        << s.triangleFace[t] << '\n';
}

}  // namespace cadmedial
