// The sample spacing a face needs, as a field over its UV box rather than one
// number: 0.15 × the local radius of curvature (on a 17 × 17 node grid) and
// 0.4 × the local wall thickness (rays from a 7 × 7 grid, each good for its
// grid cell), graded so that it grows by at most kGrading per unit of
// distance. One face-wide minimum let a single sharp spot (a
// cone's apex, a thin flange on one side of a big face) set the spacing of
// the whole face: 115 k samples on a pointed cone, 11 k with the field.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include <Adaptor3d_Surface.hxx>
#include <gp_Pnt.hxx>

#include <TopoDS_Face.hxx>

#include "spacing_sources.hpp"

#include "solid_ray_caster.hpp"

namespace cadmedial {

class FaceSpacingField {
 public:
  static constexpr double kCurvatureFraction = 0.15;  // spacing <= this × radius of curvature (chord error ~0.3 %)
  static constexpr double kThicknessFraction = 0.4;   // spacing <= this × local wall thickness
  static constexpr double kWidthFraction = 0.5;       // spacing <= this × the face's local width (narrow_faces.hpp)
  static constexpr double kGrading = 0.15;            // spacing grows by at most this × distance
  // Away from a convex edge whose spacing is finer than the face's (a hole's
  // rim in a plate, computeSpacings): a ball of the edge's sheet touching the
  // face about r from the edge then meets samples spaced ~0.5 r, and pokes
  // through the face between them by about (0.5 r / 2)² / (2 r) ≈ 3 % of r.
  // Measured on the bundled flange (two contacts, samples): without it
  // 85 %, 5.5 k; with 0.5 98.8 %, 7.7 k. In a first version (tile-wide
  // dart radii, edges not spaced again) 0.15 / 0.3 / 0.5 / 0.8 gave
  // 99.7 / 99.7 / 99.6 / 99.1 % with 14.5 / 10.7 / 8.9 / 7.0 k samples.
  static constexpr double kConvexEdgeGrading = 0.5;

  // The tolerance to load `solidRays` with, and how far from its start a
  // ray's first hit must be to count as a wall, for a spacing h. OCCT's
  // usual 1e-7 (mm) is not small next to a part a few mm wide: on a box of
  // 6 µm (h 0.2 µm) every ray found its own face at the skip distance h/10⁶,
  // a wall that thin, and the part took 745 k samples instead of 5 k. The
  // tolerance is OCCT's usual for h ≥ 0.01 and 1e-5 h below; the skip is
  // 1e-6 h for h ≥ 1 (as before), 1e-6 for 0.01 ≤ h < 1 and 1e-4 h below.
  static double rayTolerance(double h) { return std::min(1e-7, 1e-5 * h); }
  static double raySkip(double h) { return std::max(1e-6 * h, 10 * rayTolerance(h)); }
  // A hit on the ray's own face closer than this to its start p is not a
  // wall either: the face can come back further than the skip where the
  // coordinates are large, as OCCT's intersector is good to ~1e-11 of them
  // (a part 100 m from the origin: 2.5e-6 mm off, an 8e-7 h thick wall, and
  // 3 × the samples). Telling the ray's entry from its exit by the hit's
  // transition would not need a distance; not tried.
  static double ownFaceReach(double h, const gp_Pnt& p) {
    return 1e-3 * h + 1e-9 * (std::abs(p.X()) + std::abs(p.Y()) + std::abs(p.Z()));
  }

  // Probes `face` (curvature on a node grid, wall thickness by rays cast
  // inward through `solidRays`, loaded with rayTolerance(cap)), clamps every value to [floor, cap] and grades
  // it. `cap` is the global target spacing h. Not `graded`: one value for the
  // whole face, the smallest curvature bound on a 9 × 9 grid and the smallest
  // ray probe (the rule before the field; `--uniform-spacing`, see
  // SamplingParams::gradedSpacing).
  // `boundsScale` multiplies the curvature and thickness fractions
  // (SamplingParams::boundsScale).
  FaceSpacingField(const TopoDS_Face& face, SolidRayCaster& solidRays, double floor, double cap,
                   bool graded, double boundsScale = 1.0);

  // Graded from sources outside the face too (points on its convex edges,
  // with the edges' spacing): the spacing anywhere becomes at most a source's
  // spacing + grading × its distance to it. The nodes take it, so the cells
  // do, and at() and sourcesAllow() ask the sources themselves where a cell
  // is too coarse to show it. No effect on a field that is not graded (one
  // value per face). Once per field: a second call replaces the sources.
  using Source = SpacingSources::Source;
  void gradeFrom(std::vector<Source> sources, double grading);

  // The spacing at the point p = S(u, v) of the face: its grid cell's (the
  // smallest value on the cell's corners and probes, so the cell never asks
  // for more than a point in it needs), or less near a source.
  double at(double u, double v, const gp_Pnt& p) const;
  // The smallest that at() can be anywhere in the cell holding (u, v), as
  // far as the ball estimated to hold the cell goes (ballHolding): cheap (no
  // search), for rejecting a dart that is not clear even at that.
  double lowestNear(double u, double v) const;
  // The smallest spacing over the cells that a UV box overlaps; where
  // nearSources(box), the sources may ask for less inside it:
  // sourcesAllow(a ball holding the box's points, that minimum) says how much.
  double minOver(double uLow, double uHigh, double vLow, double vHigh) const;
  bool nearSources(double uLow, double uHigh, double vLow, double vHigh) const;
  double sourcesAllow(const gp_Pnt& centre, double radius, double upTo) const;
  double minimum() const { return minimum_; }
  // The thinnest wall the ray probes found (1e300 if none): below
  // floor / kThicknessFraction the spacing cannot follow it.
  double thinnestWall() const { return thinnestWall_; }
  const gp_Pnt& thinnestWallAt() const { return thinnestWallAt_; }  // the probe's point on the face

  // A ball about S(centre of the UV box) that holds the box's points, from
  // the corners, the sides' midpoints and the centres of the four quarters,
  // with a 25 % margin. An estimate, not a bound: a box wrapping more than
  // half a turn of a surface can reach beyond it (then a dart near a source
  // takes its cell's spacing, the grading at the nodes only).
  struct Ball {
    gp_Pnt centre;
    double radius;
  };
  static Ball ballHolding(const Adaptor3d_Surface& surface, double uLow, double uHigh, double vLow, double vHigh);
  double maximum() const { return maximum_; }

 private:
  int cellIndex(double x, double low, double high) const;      // cell holding x
  int lastCellIndex(double x, double low, double high) const;  // last cell a range ending at x reaches
  template <typename Visit>
  void forCellsOver(double uLow, double uHigh, double vLow, double vHigh, Visit visit) const;

  void computeCells();  // from nodes_ and probes_

  static constexpr int kCells = 16;  // per UV side
  double u0_ = 0, u1_ = 1, v0_ = 0, v1_ = 1;
  bool graded_ = false;
  std::vector<gp_Pnt> nodePoints_;  // (kCells + 1)², row-major in v (graded only)
  std::vector<double> nodes_;       // graded spacing at each node
  std::vector<std::array<double, 3>> probes_;  // thickness probes: u, v, spacing (graded only)
  std::vector<double> cells_;  // kCells², row-major in v: min of corners and probes
  // Graded only: a ball that holds each cell, and the smallest spacing the
  // sources allow in it (cells where it is no smaller than the cell's own
  // skip the search).
  std::vector<Ball> cellBalls_;
  std::vector<double> sourceFloor_;
  std::unique_ptr<SpacingSources> sources_;
  double minimum_ = 0, maximum_ = 0;
  double thinnestWall_ = 1e300;
  gp_Pnt thinnestWallAt_;
};

}  // namespace cadmedial
