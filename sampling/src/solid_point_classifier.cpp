#include "solid_point_classifier.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <BRepBndLib.hxx>
#include <BRepClass3d_BndBoxTree.hxx>
#include <Bnd_Box.hxx>
#include <Precision.hxx>
#include <gp_Lin.hxx>

namespace cadmedial {

namespace {

// Generic directions (no two parallel, none along an axis or a diagonal,
// where CAD faces and edges tend to lie): the ray seldom grazes an edge.
constexpr int kDirections = 8;
const std::array<gp_Dir, kDirections>& rayDirections() {
  static const std::array<gp_Dir, kDirections> directions{
      gp_Dir(0.5377, 0.8034, 0.2557),  gp_Dir(-0.7311, 0.1742, 0.6597), gp_Dir(0.2231, -0.6917, 0.6868),
      gp_Dir(-0.3319, -0.4213, -0.8441), gp_Dir(0.8719, -0.2917, -0.3933), gp_Dir(-0.1637, 0.9311, -0.3260),
      gp_Dir(0.6143, 0.3371, -0.7134), gp_Dir(-0.8923, -0.4012, 0.2071)};
  return directions;
}

}  // namespace

SolidPointClassifier::SolidPointClassifier(const TopoDS_Shape& solid)
    : explorer_(solid), rays_(solid, Precision::Confusion(), /*nearEdgesToo=*/true) {
  Bnd_Box box;
  BRepBndLib::Add(solid, box);
  diagonal_ = box.IsVoid() ? 0 : std::sqrt(box.SquareExtent());
  surfaces_.resize(static_cast<std::size_t>(rays_.faceCount()));
  // A ray that meets nothing says OUT only if the solid's outside is
  // outside: a clean ray from beyond its box must first enter it. An
  // inverted solid (its faces turned inwards), or one no clean ray tells,
  // is left to OCCT's classifier for every query.
  if (box.IsVoid()) return;
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  const gp_Pnt centre((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2);
  for (const gp_Dir& direction : rayDirections()) {
    const gp_Pnt far = centre.Translated(-gp_Vec(direction) * diagonal_);  // beyond the box
    IntCurveSurface_TransitionOnCurve first = IntCurveSurface_Tangent;
    if (cleanRay(far, direction, 0, first) == RaySays::Clean && first != IntCurveSurface_Tangent) {
      outsideIsOut_ = first == IntCurveSurface_In;  // a hit, and the first one enters
      break;
    }
  }
}

// Casts from p along `direction`; `first` gets the transition of the first
// hit beyond `onReach` (Tangent if none).
SolidPointClassifier::RaySays SolidPointClassifier::cleanRay(const gp_Pnt& p, const gp_Dir& direction, double onReach,
                                                            IntCurveSurface_TransitionOnCurve& first) {
  // The rays start a little behind the point, so that a hit at the point
  // itself (on a face) lies inside the searched segment rather than at its
  // end, where the polyhedron-based B-spline search is least sure (a
  // precaution: the test points on faces pass without it too).
  if (!rays_.cast(gp_Lin(p, direction), -(onReach + 1e-6 * diagonal_), 1e300, hits_)) return RaySays::Unclean;
  bool clean = true, on = false;
  const SolidRayCaster::Hit* previous = nullptr;
  for (const SolidRayCaster::Hit& hit : hits_) {
    if (std::abs(hit.w) <= onReach) on = true;
    if (hit.w <= onReach) continue;  // behind the point
    // An internal or external face does not part inside from outside (and
    // its transition is the bare surface's): not counted, so not used.
    const TopAbs_Orientation orientation = rays_.face(hit.face).Orientation();
    clean = clean && !hit.onEdge && hit.transition != IntCurveSurface_Tangent &&
            (orientation == TopAbs_FORWARD || orientation == TopAbs_REVERSED) &&
            (!previous || hit.transition != previous->transition) && !grazes(hit, direction);
    if (!previous) first = hit.transition;
    previous = &hit;
  }
  if (on) return RaySays::On;
  if (!clean || (previous && previous->transition != IntCurveSurface_Out)) return RaySays::Unclean;
  return RaySays::Clean;
}

// A ray nearly along the surface where it crosses can miss a second
// crossing close by (a ray grazing a B-spline fillet found its exit, not
// its entry at the point itself): such rays are not used.
bool SolidPointClassifier::grazes(const SolidRayCaster::Hit& hit, const gp_Dir& direction) {
  constexpr double kGrazingSine = 0.1;  // within ~6° of the surface
  std::unique_ptr<BRepAdaptor_Surface>& surface = surfaces_[static_cast<std::size_t>(hit.face)];
  if (!surface) surface = std::make_unique<BRepAdaptor_Surface>(rays_.face(hit.face));
  gp_Pnt point;
  gp_Vec du, dv;
  surface->D1(hit.u, hit.v, point, du, dv);
  const gp_Vec normal = du.Crossed(dv);
  const double length = normal.Magnitude();
  return !(length > 0) || std::abs(normal.Dot(gp_Vec(direction))) < kGrazingSine * length;
}

TopAbs_State SolidPointClassifier::classify(const gp_Pnt& p, double tolerance) {
  // Within an edge's or vertex's tolerance: ON, the classifier's first test.
  BRepClass3d_BndBoxTreeSelectorPoint nearEdges(explorer_.GetMapEV());
  nearEdges.SetCurrentPoint(p);
  if (explorer_.GetTree().Select(nearEdges) > 0) return TopAbs_ON;

  // Rays only where the outside was found to be outside (not on an inverted
  // solid, nor on one without faces: the whole space to OCCT).
  if (outsideIsOut_) {
    const double onReach = std::max(tolerance, 0.0);
    for (const gp_Dir& direction : rayDirections()) {
      IntCurveSurface_TransitionOnCurve first = IntCurveSurface_Tangent;
      const RaySays says = cleanRay(p, direction, onReach, first);
      if (says == RaySays::On) return TopAbs_ON;
      if (says == RaySays::Clean) return first == IntCurveSurface_Out ? TopAbs_IN : TopAbs_OUT;
    }
  }
  ++fallbacks_;
  occt_.Perform(explorer_, p, tolerance);
  return occt_.State();
}

}  // namespace cadmedial
