// Tangent polygons and umbrellas of MEDIAL (seed 000, Def. 2 and 3).
//
// The tangent polygon of p is the section of V_p by the plane through p with
// the pole vector v_p as normal. The Voronoi edges of V_p it crosses are dual
// to Delaunay triangles pqr; those triangles are p's umbrella, which lies flat
// to the surface and stands in for the B-rep reconstruction that CAD_MEDIAL
// takes its umbrellas from. The Angle/Ratio selection is shared (umbrella.hpp,
// facet_selection.hpp); only where the umbrella triangles come from differs.
//
// A Voronoi edge (segment c1c2 or ray c1 + t·d, t ≥ 0) is crossed when its
// ends lie on different sides of the plane, with the half-open rule
// (side ≤ 0 vs > 0), so an edge that only touches the plane at a Voronoi
// vertex is counted on one side, and zero-length edges between coincident
// circumcentres (cospherical samples) are never crossed.
#pragma once

#include <array>
#include <vector>

#include "cadmedial/delaunay.hpp"
#include "cadmedial/medial_poles.hpp"
#include "cadmedial/umbrella.hpp"

namespace cadmedial {

struct TangentPolygonUmbrellas {
  // Umbrella of canonical sample p: triangles[offsets[p] .. offsets[p+1]),
  // each (p, q, r) in canonical sample ids. A triangle appears once per
  // sample whose umbrella holds it.
  std::vector<std::array<Index, 3>> triangles;
  std::vector<Index> offsets;
  std::size_t emptyUmbrellas = 0;  // canonical samples whose tangent polygon crossed no Voronoi edge
  double seconds = 0;
};

TangentPolygonUmbrellas computeTangentPolygonUmbrellas(const DelaunayVoronoi& dv, const PoleData& poles);

// The umbrellas in the form the Angle/Ratio selection uses (normals, largest
// circumradius per sample).
UmbrellaData umbrellaDataOf(const std::vector<Vec3>& points, const TangentPolygonUmbrellas& umbrellas);

}  // namespace cadmedial
