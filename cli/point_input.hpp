// Reading point clouds and triangle meshes for MEDIAL (`cadmedial run` on
// inputs without a B-rep).
//   point clouds: .xyz, .pts (x y z per line, further columns ignored, an
//                 optional first line with the point count), .ply without faces
//   meshes:       .stl, .obj, .off, .ply with faces (vertices are the samples;
//                 polygons are fan-triangulated for the inside test)
#pragma once

#include <array>
#include <string>
#include <vector>

#include "cadmedial/sample_set.hpp"

namespace cadmedial {

struct PointInput {
  std::string path;
  std::string format;  // "xyz", "pts", "ply", "stl", "obj", "off"
  bool isMesh = false;  // triangles were read
  std::vector<Vec3> points;
  std::vector<std::array<Index, 3>> triangles;
  std::vector<std::string> warnings;
};

// True for the extensions above (any case).
bool isPointInputPath(const std::string& path);

// Throws InputError(kExitUnreadableInput) with a one-line message for a
// missing, empty or malformed file, non-finite coordinates, face indices out
// of range, or fewer than 4 points.
PointInput readPointInput(const std::string& path);

}  // namespace cadmedial
