// Shapes for the ray caster and point classifier tests (sampling/src/
// solid_ray_caster.*, solid_point_classifier.*).
#pragma once

#include <random>
#include <vector>

#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>

namespace cadmedial::test {

// A 30 x 20 x 10 box with every edge filleted (r 2): cylinders, spheres' blends.
TopoDS_Shape filletedBox();
// A surface of revolution (an ellipse arc turned 270°) fused with a surface
// of extrusion (a closed Bezier curve pushed up): faces that BRepBndLib
// boxes by sampling.
TopoDS_Shape revolvedAndExtruded();

// `count` points uniform in the shape's bounding box grown by 20 % each way.
std::vector<gp_Pnt> pointsAround(const TopoDS_Shape& shape, int count, std::mt19937& random);

}  // namespace cadmedial::test
