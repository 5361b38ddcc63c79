// The exact medial axis of models/box.step, built by hand, and the
// perturbations the evaluation must reject.
#pragma once

#include <array>

#include "cadmedial/medial_evaluation.hpp"

namespace cadmedial::test {

// Box [0,40]x[0,30]x[0,20] (MakeBox(40, 30, 20), models/EXPECTED.md). Its
// medial axis is where the two nearest face planes tie. With half-height
// 10 (the smallest half-extent) it is 13 planar pieces, one sheet each:
//   * the rectangle z = 10, x in [10,30], y in [10,20] (faces z=0 and z=20 tie), r = 10;
//   * per edge along x (y,z in {0,30}x{0,20}): the bisector trapezoid
//     {y' = z' = t, x in [t, 40-t], t in [0,10]} (y', z' measured from the
//     edge's two faces), r = t, e.g. (0,0,0) (40,0,0) (30,10,10) (10,10,10);
//   * per edge along y: {x' = z' = t, y in [t, 30-t], t in [0,10]}, r = t;
//   * per edge along z: the triangle {x' = y' = t, z in [t, 20-t], t in [0,10]}, r = t,
//     apex (10,10,10) at the rectangle's corner.
// The opposite-face bisectors x = 20 and y = 15 are not part of it (there
// the faces z = 0 / z = 20 are nearer). Pieces meet along the lines
// x' = y' = z' = t from each box corner to a rectangle corner and along the
// rectangle's sides. Every piece is triangulated on one lattice of step
// 10/rowsPerHalf, so shared lines have the same vertices and edges; radii
// are exact (min of the six face distances).
MedialMesh exactBoxAxis(int rowsPerHalf = 25);

constexpr std::array<double, 3> kBoxCentre{20, 15, 10};

MedialMesh scaledRadii(MedialMesh mesh, double factor);
MedialMesh shrunkToward(MedialMesh mesh, const std::array<double, 3>& centre, double factor);  // radii kept
MedialMesh translated(MedialMesh mesh, const std::array<double, 3>& offset);
MedialMesh withoutSheet(const MedialMesh& mesh, int sheet);  // polygons of that sheet removed

}  // namespace cadmedial::test
