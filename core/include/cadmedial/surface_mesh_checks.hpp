// Checks of a triangle surface over indexed points: is it closed, 2-manifold
// and consistently oriented; its Euler characteristic, area and the volume it
// encloses (divergence theorem).
#pragma once

#include <array>
#include <vector>

#include "cadmedial/sample_set.hpp"

namespace cadmedial {

struct SurfaceMeshStats {
  std::size_t vertices = 0;  // points used by some triangle
  std::size_t edges = 0;
  std::size_t triangles = 0;
  std::size_t boundaryEdges = 0;       // used by one triangle
  std::size_t nonManifoldEdges = 0;    // used by more than two triangles
  std::size_t misorientedEdges = 0;    // used twice in the same direction
  std::size_t nonManifoldVertices = 0; // umbrella is not one disc
  std::size_t components = 0;
  long eulerCharacteristic = 0;  // V - E + F
  double area = 0;
  double enclosedVolume = 0;     // positive for outward-oriented closed surfaces

  bool closedManifold() const {
    return boundaryEdges == 0 && nonManifoldEdges == 0 && misorientedEdges == 0 && nonManifoldVertices == 0;
  }
  // Genus of a closed orientable surface with `components` components.
  double genus() const { return (2.0 * static_cast<double>(components) - static_cast<double>(eulerCharacteristic)) / 2.0; }
};

SurfaceMeshStats checkSurfaceMesh(const std::vector<Vec3>& points, const std::vector<std::array<Index, 3>>& triangles);

}  // namespace cadmedial
