// Synthetic SampleSets for core/ tests, without OCCT: planar-faced solids
// (box, L-prism, box with a square through-hole) sampled the way DESIGN.md §3
// asks (corner balls, edge samples, convex-edge triplets with equal
// perpendicular legs, well-spaced non-grid face samples kept clear of the
// triplet band, per-face constrained Delaunay umbrellas), a regular-grid box
// (maximally degenerate), and ellipsoid point clouds with convex-hull umbrellas.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "cadmedial/sample_set.hpp"

namespace cadmedial::testing {

using Vec2 = std::array<double, 2>;

struct PlanarFace {
  // loops[0]: outer boundary, counter-clockwise seen from outside the solid;
  // loops[1..]: holes, clockwise seen from outside.
  std::vector<std::vector<Vec3>> loops;
};

struct PlanarSolid {
  std::string name;
  std::vector<PlanarFace> faces;
  std::function<bool(const Vec3&)> inside;  // exact inside test
  std::function<double(const Vec3&)> boundaryDistance;  // exact distance to the boundary (inside points)
};

// Prism over a 2D polygon (outer CCW, holes CW) between z = 0 and z = height.
PlanarSolid extrudedPolygon(std::string name, const std::vector<Vec2>& outer, const std::vector<std::vector<Vec2>>& holes,
                            double height);
PlanarSolid makeBox(double a, double b, double c);
PlanarSolid makeLPrism();           // L of 2 x 2 with a 1 x 1 notch, height 0.8
PlanarSolid makeBoxWithSquareHole();  // 2 x 2 x 0.6 with a 0.8 x 0.8 hole (genus 1)

struct SamplingOptions {
  double spacing = 0.05;       // h
  unsigned seed = 1;
  double cornerBall = 0.5;     // corner ball radius / h
  double edgeStep = 0.5;       // max edge sample spacing / h
  double leg = 0.4;            // triplet leg length / h
  double faceMinDistance = 0.7;  // Poisson-disk radius of face samples / h
  double clearance = 0.65;     // face samples keep this distance / h from every edge (> leg: the triplet band)
};

// Non-concave corner rule used here: a vertex is non-concave iff one of its
// edges is convex (right for the test solids above; not a general rule).
SampleSet samplePlanarSolid(const PlanarSolid& solid, const SamplingOptions& options);

// Box [0,n·h]^3 sampled on the regular surface grid of step h (every grid
// point on the surface), triplets from grid neighbours, grid triangulation.
SampleSet gridBoxSamples(int n, double h);

// Points on the ellipsoid x²/a² + y²/b² + z²/c² = 1 (Fibonacci lattice mapped
// to the ellipsoid, slightly jittered), umbrellas from the convex hull.
SampleSet ellipsoidCloud(const Vec3& axes, std::size_t count, unsigned seed, double jitter = 0.2);

// Recompute SampleSet::triangles as the convex hull of the points (outward).
void hullUmbrellas(SampleSet& s);

// Fill per-point arrays for a bare point cloud (all Face, owner 0) and bbox.
void finishPointCloud(SampleSet& s);

}  // namespace cadmedial::testing
