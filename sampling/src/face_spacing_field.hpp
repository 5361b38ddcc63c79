// The sample spacing a face needs, as a field over its UV box rather than one
// number: 0.15 × the local radius of curvature (on a 17 × 17 node grid) and
// 0.4 × the local wall thickness (rays from a 7 × 7 grid, each good for its
// grid cell), graded so that it grows by at most kGrading per unit of
// distance. One face-wide minimum let a single sharp spot (a
// cone's apex, a thin flange on one side of a big face) set the spacing of
// the whole face: 115 k samples on a pointed cone, 11 k with the field.
#pragma once

#include <vector>

#include <IntCurvesFace_ShapeIntersector.hxx>
#include <TopoDS_Face.hxx>

namespace cadmedial {

class FaceSpacingField {
 public:
  static constexpr double kCurvatureFraction = 0.15;  // spacing <= this × radius of curvature (chord error ~0.3 %)
  static constexpr double kThicknessFraction = 0.4;   // spacing <= this × local wall thickness
  static constexpr double kGrading = 0.15;            // spacing grows by at most this × distance

  // Probes `face` (curvature on a node grid, wall thickness by rays cast
  // inward through `solidRays`), clamps every value to [floor, cap] and grades
  // it. `cap` is the global target spacing h. Not `graded`: one value for the
  // whole face, the smallest curvature bound on a 9 × 9 grid and the smallest
  // ray probe (the rule before the field; still the default, see
  // SamplingParams::gradedSpacing).
  // `boundsScale` multiplies the curvature and thickness fractions
  // (SamplingParams::boundsScale).
  FaceSpacingField(const TopoDS_Face& face, IntCurvesFace_ShapeIntersector& solidRays, double floor, double cap,
                   bool graded, double boundsScale = 1.0);

  // The spacing of the grid cell holding (u, v): the smallest value on its
  // corners and probes, so the cell never asks for more than a point in it
  // needs.
  double at(double u, double v) const;
  // The smallest spacing over the cells that a UV box overlaps.
  double minOver(double uLow, double uHigh, double vLow, double vHigh) const;
  double minimum() const { return minimum_; }
  double maximum() const { return maximum_; }

 private:
  int cellIndex(double x, double low, double high) const;      // cell holding x
  int lastCellIndex(double x, double low, double high) const;  // last cell a range ending at x reaches

  static constexpr int kCells = 16;  // per UV side
  double u0_ = 0, u1_ = 1, v0_ = 0, v1_ = 1;
  std::vector<double> cells_;  // kCells², row-major in v: min of corners and probes
  double minimum_ = 0, maximum_ = 0;
};

}  // namespace cadmedial
