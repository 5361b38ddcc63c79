// Smooth closed surfaces with exactly known medial axes, for measuring MEDIAL
// (seed 000) on point clouds against exact geometry:
//   sphere    radius R: inner axis = the centre, no outer axis;
//   ellipsoid a > b > c: inner axis = the region z = 0 inside the focal ellipse
//             with semi-axes (a²−c²)/a, (b²−c²)/b; no outer axis (convex);
//   torus     R > r: inner axis = the core circle; outer axis = the z axis
//             (every point of it sees a whole circle of closest points).
// Distances to the surface are exact (closed form; ellipsoid by Eberly's
// bisection on the Lagrange multiplier, robust for points inside and outside
// and on the symmetry planes).
#pragma once

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "cadmedial/medial.hpp"

namespace cadmedial::testing {

class AnalyticShape {
 public:
  virtual ~AnalyticShape() = default;
  virtual std::string name() const = 0;
  virtual double surfaceArea() const = 0;
  virtual double diagonal() const = 0;          // of the bounding box
  virtual bool inside(const Vec3& p) const = 0;
  virtual double surfaceDistance(const Vec3& p) const = 0;  // unsigned, exact
  virtual double innerAxisDistance(const Vec3& p) const = 0;
  virtual double wholeAxisDistance(const Vec3& p) const = 0;  // to inner ∪ outer axis
  // One area-uniform random point on the surface.
  virtual Vec3 randomSurfacePoint(std::mt19937& rng) const = 0;
};

std::unique_ptr<AnalyticShape> makeSphere(double radius);
std::unique_ptr<AnalyticShape> makeEllipsoid(double a, double b, double c);  // a > b > c
std::unique_ptr<AnalyticShape> makeTorus(double majorRadius, double minorRadius);

// Distance from p to the ellipsoid x²/a² + y²/b² + z²/c² = 1 (a ≥ b ≥ c > 0).
double ellipsoidDistance(const Vec3& axes, const Vec3& p);
// Distance from (x, y) to the filled ellipse x²/A² + y²/B² ≤ 1 (0 inside).
double filledEllipseDistance(double A, double B, double x, double y);

// About `count` well-spaced surface points: area-uniform random candidates
// thinned greedily to a minimum distance (Poisson disk, never a grid), then
// every point moved by a uniform random vector in the cube
// [-noise, noise]³ × diagonal (noise = 0.001 is "0.1 % noise").
std::vector<Vec3> sampleSurface(const AnalyticShape& shape, std::size_t count, unsigned seed, double noise = 0);

// A medial axis measured against the exact shape (DESIGN.md §6 quantities;
// lengths relative to the bounding-box diagonal, tol = 0.005).
struct AnalyticMeasure {
  std::size_t vertices = 0;          // polygon vertices with r > 0
  double medialMedian = 0, medialP90 = 0;  // |dist(v, S) − r(v)|
  double axisMedian = 0, axisP90 = 0, axisP99 = 0, axisMax = 0;  // dist(v, exact axis)
  double farShare = 0;               // vertices farther than 2 tol from the exact axis
  double coverage = 0;               // boundary points within tol of a ball of an inside vertex
  double insideShare = 0;            // vertices inside the shape
};
AnalyticMeasure measureAgainstShape(const MedialComplex& axis, const AnalyticShape& shape, bool wholeAxis,
                                    std::size_t boundaryPoints = 10000, double tolFraction = 0.005);

}  // namespace cadmedial::testing
