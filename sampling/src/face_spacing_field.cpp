#include "face_spacing_field.hpp"

#include <algorithm>
#include <cmath>

#include <BRepAdaptor_Surface.hxx>
#include <BRepLProp_SLProps.hxx>
#include <BRepTools.hxx>
#include <gp_Lin.hxx>

#include "face_uv_classifier.hpp"
#include "solid_topology.hpp"

namespace cadmedial {

namespace {

struct Probe {
  gp_Pnt point;
  double u, v;
  double spacing;
  double reach = 0;  // the probe's value holds unchanged this far (3D) before grading starts
  double wall = 0;   // the wall thickness the ray found
};

// Wall thickness seen from a point of the face: a ray cast inward along the
// normal, to the first boundary hit. The medial ball of a wall of thickness t
// has radius t/2, so a thin wall needs samples spaced well below t for the
// Voronoi facets between its sides to be medial. A probe holds 0.4 × t,
// clamped to the spacing range.
class ThicknessProber {
 public:
  ThicknessProber(const TopoDS_Face& face, const BRepAdaptor_Surface& surf, SolidRayCaster& rays,
                  double floor, double cap, double fraction)
      : face_(face), surf_(surf), rays_(rays), inFace_(face, 1e-9), floor_(floor), cap_(cap), fraction_(fraction) {}

  // False where (u, v) is off the face, the normal is undefined or no
  // boundary lies behind the point. The probe stands for the UV cell
  // (u, v) ± (du, dv) / 2 and its neighbours: its reach is the cell's 3D
  // diagonal, so a wall of even thickness gets the same spacing between the
  // probes as at them.
  bool probe(double u, double v, double du, double dv, Probe& out) {
    const gp_Pnt2d uv(u, v);
    if (inFace_.Perform(uv) != TopAbs_IN) return false;
    const gp_Vec normal = outwardNormalAt(face_, uv);
    if (normal.Magnitude() < 0.5) return false;
    const gp_Pnt p = surf_.Value(u, v);
    // The skip leaves out the face the ray starts on.
    if (!rays_.cast(gp_Lin(p, gp_Dir(-normal)), FaceSpacingField::raySkip(cap_), 1e300, hits_)) return false;
    const double ownFaceLimit = FaceSpacingField::ownFaceReach(cap_, p);
    double thickness = 1e300;
    for (const SolidRayCaster::Hit& hit : hits_) {
      if (hit.w < ownFaceLimit && rays_.face(hit.face).IsSame(face_)) continue;
      thickness = std::min(thickness, hit.w);
    }
    if (!(thickness < 1e300)) return false;
    const double reach = std::max(surf_.Value(u - du / 2, v - dv / 2).Distance(surf_.Value(u + du / 2, v + dv / 2)),
                                  surf_.Value(u - du / 2, v + dv / 2).Distance(surf_.Value(u + du / 2, v - dv / 2)));
    out = {p, u, v, std::clamp(fraction_ * thickness, floor_, cap_), reach, thickness};
    return true;
  }

 private:
  const TopoDS_Face& face_;
  const BRepAdaptor_Surface& surf_;
  SolidRayCaster& rays_;
  std::vector<SolidRayCaster::Hit> hits_;
  FaceUVClassifier inFace_;
  double floor_, cap_;
  double fraction_;  // of the thickness
};

// Thickness probes on a 7 × 7 grid (rays cost ~0.1 ms each, so not one per
// field cell). Refining the grid where neighbouring probes disagree was
// tried: near an acute wedge it found the thin rim in some directions and not
// in others, and the spotty field did worse than this one.
std::vector<Probe> thicknessProbes(ThicknessProber& prober, double u0, double u1, double v0, double v1) {
  constexpr int n = 7;
  std::vector<Probe> probes;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      Probe p;
      if (prober.probe(u0 + (u1 - u0) * (i + 0.5) / n, v0 + (v1 - v0) * (j + 0.5) / n, (u1 - u0) / n, (v1 - v0) / n,
                       p))
        probes.push_back(p);
    }
  return probes;
}

// Largest principal curvature at (u, v), or, where it is not defined (a
// cone's apex, a sphere's pole), the largest seen on points approaching it
// from the four diagonal directions at 1/4, 1/16, ... 1/4096 of a grid cell:
// at an apex the curvature grows without bound as the points close in, so the
// spacing there drops to the floor; at a pole it stays that of the sphere.
// Returns 0 if no curvature is found at all.
double curvatureAt(const BRepAdaptor_Surface& surf, double u, double v, double du, double dv, double u0, double u1,
                   double v0, double v1) {
  BRepLProp_SLProps props(surf, u, v, 2, 1e-9);
  auto largest = [&]() { return std::max(std::abs(props.MaxCurvature()), std::abs(props.MinCurvature())); };
  if (props.IsCurvatureDefined()) return largest();
  double k = 0;
  for (double step = 0.25; step > 1.0 / 5000; step *= 0.25)
    for (int su : {-1, 1})
      for (int sv : {-1, 1}) {
        const double a = std::clamp(u + su * step * du, u0, u1), b = std::clamp(v + sv * step * dv, v0, v1);
        if (a == u && b == v) continue;
        props.SetParameters(a, b);
        if (props.IsCurvatureDefined()) k = std::max(k, largest());
      }
  return k;
}

}  // namespace

FaceSpacingField::FaceSpacingField(const TopoDS_Face& face, SolidRayCaster& solidRays, double floor,
                                   double cap, bool graded, double boundsScale) {
  const double curvatureFraction = kCurvatureFraction * boundsScale;
  BRepAdaptor_Surface surf(face, true);
  BRepTools::UVBounds(face, u0_, u1_, v0_, v1_);
  ThicknessProber prober(face, surf, solidRays, floor, cap, kThicknessFraction * boundsScale);
  const std::vector<Probe> thickness = thicknessProbes(prober, u0_, u1_, v0_, v1_);
  for (const Probe& p : thickness)
    if (p.wall < thinnestWall_) {
      thinnestWall_ = p.wall;
      thinnestWallAt_ = p.point;
    }

  if (!graded) {
    // One number for the whole face: the smallest curvature bound on a 9 × 9
    // grid of cell centres and the smallest ray probe.
    double maxK = 0;
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j) {
        BRepLProp_SLProps props(surf, u0_ + (u1_ - u0_) * (i + 0.5) / 9, v0_ + (v1_ - v0_) * (j + 0.5) / 9, 2, 1e-9);
        if (!props.IsCurvatureDefined()) continue;
        maxK = std::max({maxK, std::abs(props.MaxCurvature()), std::abs(props.MinCurvature())});
      }
    double uniform = curvatureFraction * (maxK > 0 ? 1.0 / maxK : 1e300);
    for (const Probe& p : thickness) uniform = std::min(uniform, p.spacing);
    cells_.assign(kCells * kCells, std::clamp(uniform, floor, cap));
    minimum_ = maximum_ = cells_.front();
    return;
  }

  // Nodes: the curvature bound, then graded: s_i = min over all sources j of
  // s_j + kGrading × |P_i - P_j| (less the reach of a thickness probe).
  // Straight-line distance is at most the distance along the face, so this
  // errs towards smaller spacings. Sources are the nodes (as measured) and
  // the thickness probes.
  constexpr int nodesPerSide = kCells + 1;
  std::vector<gp_Pnt> points;
  std::vector<double> measured;
  for (int j = 0; j < nodesPerSide; ++j)
    for (int i = 0; i < nodesPerSide; ++i) {
      const double u = u0_ + (u1_ - u0_) * i / kCells, v = v0_ + (v1_ - v0_) * j / kCells;
      const double k = curvatureAt(surf, u, v, (u1_ - u0_) / kCells, (v1_ - v0_) / kCells, u0_, u1_, v0_, v1_);
      measured.push_back(k > 0 ? std::clamp(curvatureFraction / k, floor, cap) : cap);
      points.push_back(surf.Value(u, v));
    }
  std::vector<double> node = measured;
  for (std::size_t a = 0; a < points.size(); ++a) {
    for (std::size_t b = 0; b < points.size(); ++b)
      node[a] = std::min(node[a], measured[b] + kGrading * points[a].Distance(points[b]));
    for (const Probe& p : thickness)
      node[a] = std::min(node[a], p.spacing + kGrading * std::max(0.0, points[a].Distance(p.point) - p.reach));
  }
  graded_ = true;
  nodePoints_ = std::move(points);
  nodes_ = std::move(node);
  for (const Probe& p : thickness) probes_.push_back({p.u, p.v, p.spacing});
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      const double du = (u1_ - u0_) / kCells, dv = (v1_ - v0_) / kCells;
      cellBalls_.push_back(ballHolding(surf, u0_ + du * i, u0_ + du * (i + 1), v0_ + dv * j, v0_ + dv * (j + 1)));
    }
  computeCells();
}

FaceSpacingField::Ball FaceSpacingField::ballHolding(const Adaptor3d_Surface& surface, double uLow, double uHigh,
                                                     double vLow, double vHigh) {
  const double uMid = (uLow + uHigh) / 2, vMid = (vLow + vHigh) / 2;
  const gp_Pnt centre = surface.Value(uMid, vMid);
  // Corners, sides' midpoints, quarters' centres (fractions of the box).
  static constexpr double kProbes[12][2] = {{0, 0},      {1, 0},       {0, 1},       {1, 1},
                                            {0.5, 0},    {0.5, 1},     {0, 0.5},     {1, 0.5},
                                            {0.25, 0.25}, {0.75, 0.25}, {0.25, 0.75}, {0.75, 0.75}};
  double radius = 0;
  for (const auto& [a, b] : kProbes)
    radius = std::max(radius, centre.Distance(surface.Value(uLow + (uHigh - uLow) * a, vLow + (vHigh - vLow) * b)));
  return {centre, 1.25 * radius};
}

void FaceSpacingField::gradeFrom(std::vector<Source> sources, double grading) {
  if (!graded_ || sources.empty()) return;
  sources_ = std::make_unique<SpacingSources>(std::move(sources), grading);
  for (std::size_t a = 0; a < nodes_.size(); ++a) nodes_[a] = sources_->allowedNear(nodePoints_[a], 0, nodes_[a]);
  computeCells();
  sourceFloor_.resize(cells_.size());
  for (std::size_t c = 0; c < cells_.size(); ++c)
    sourceFloor_[c] = sources_->allowedNear(cellBalls_[c].centre, cellBalls_[c].radius, cells_[c]);
  minimum_ = std::min(minimum_, sources_->finest());
}

// A cell asks for the smallest value on its corners and on the probes inside it.
void FaceSpacingField::computeCells() {
  constexpr int nodesPerSide = kCells + 1;
  cells_.resize(kCells * kCells);
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      const int n = j * nodesPerSide + i;
      cells_[j * kCells + i] =
          std::min({nodes_[n], nodes_[n + 1], nodes_[n + nodesPerSide], nodes_[n + nodesPerSide + 1]});
    }
  for (const auto& [u, v, spacing] : probes_) {
    double& cell = cells_[cellIndex(v, v0_, v1_) * kCells + cellIndex(u, u0_, u1_)];
    cell = std::min(cell, spacing);
  }
  minimum_ = *std::min_element(cells_.begin(), cells_.end());
  maximum_ = *std::max_element(cells_.begin(), cells_.end());
}

int FaceSpacingField::cellIndex(double x, double low, double high) const {
  if (!(high > low)) return 0;
  const double cell = std::floor((x - low) / (high - low) * kCells);
  return static_cast<int>(std::clamp(cell, 0.0, static_cast<double>(kCells - 1)));
}

int FaceSpacingField::lastCellIndex(double x, double low, double high) const {
  if (!(high > low)) return 0;
  const double cell = std::ceil((x - low) / (high - low) * kCells) - 1;
  return static_cast<int>(std::clamp(cell, 0.0, static_cast<double>(kCells - 1)));
}

double FaceSpacingField::at(double u, double v, const gp_Pnt& p) const {
  const int c = cellIndex(v, v0_, v1_) * kCells + cellIndex(u, u0_, u1_);
  if (!sources_ || sourceFloor_[c] >= cells_[c]) return cells_[c];
  return sources_->allowedNear(p, 0, cells_[c]);
}

double FaceSpacingField::lowestNear(double u, double v) const {
  const int c = cellIndex(v, v0_, v1_) * kCells + cellIndex(u, u0_, u1_);
  return sources_ ? std::min(cells_[c], sourceFloor_[c]) : cells_[c];
}

// A box ending exactly on a cell boundary does not reach into the next cell.
template <typename Visit>
void FaceSpacingField::forCellsOver(double uLow, double uHigh, double vLow, double vHigh, Visit visit) const {
  for (int j = cellIndex(vLow, v0_, v1_); j <= lastCellIndex(vHigh, v0_, v1_); ++j)
    for (int i = cellIndex(uLow, u0_, u1_); i <= lastCellIndex(uHigh, u0_, u1_); ++i) visit(j * kCells + i);
}

double FaceSpacingField::minOver(double uLow, double uHigh, double vLow, double vHigh) const {
  double s = maximum_;
  forCellsOver(uLow, uHigh, vLow, vHigh, [&](int c) { s = std::min(s, cells_[c]); });
  return s;
}

bool FaceSpacingField::nearSources(double uLow, double uHigh, double vLow, double vHigh) const {
  bool near = false;
  if (sources_) forCellsOver(uLow, uHigh, vLow, vHigh, [&](int c) { near = near || sourceFloor_[c] < cells_[c]; });
  return near;
}

double FaceSpacingField::sourcesAllow(const gp_Pnt& centre, double radius, double upTo) const {
  return sources_ ? sources_->allowedNear(centre, radius, upTo) : upTo;
}

}  // namespace cadmedial
