// Inside / outside / on for points against a solid, as
// BRepClass3d_SolidClassifier answers it, at a fraction of its cost on
// parts with many faces.
//
// Why: OCCT 7.6's classifier maps every edge of the solid to its faces
// again on each query (TopExp::MapShapesAndAncestors inside
// BRepClass3d_SClassifier::Perform) and intersects its ray with every face
// box: 4.7 ms a query on a plate with 100 knurl pyramids (444 corners),
// where the corner probes took 8 s and the pair-mesh's exact cell labels 42 s.
//
// How: first OCCT's own test against the edges' and vertices' tolerance
// boxes (ON there, as the classifier says). Then a ray from the point along
// fixed, generic directions through SolidRayCaster: a hit within the
// tolerance of the point is ON; the ray is used only when it is clean: no
// hit on a face's boundary (within its tolerances), tangent or grazing (within
// ~6° of the surface), transitions
// alternating, the last one leaving the solid, none on an internal or
// external face. The first hit's transition then says the side (leaving:
// inside; none: outside). When no direction gives a clean ray (the point on
// an edge's extension), and for every query on a solid whose outside a
// clean ray from beyond its box does not find outside (an inverted solid),
// OCCT's classifier decides, with the same explorer. ON means a face hit
// within `tolerance` along the first clean-or-on ray (a glancing ray can
// put a point that near a face farther along it), or within an edge's or
// vertex's own tolerance.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include <BRepAdaptor_Surface.hxx>
#include <BRepClass3d_SClassifier.hxx>
#include <BRepClass3d_SolidExplorer.hxx>
#include <TopAbs_State.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>

#include "solid_ray_caster.hpp"

namespace cadmedial {

// Not thread-safe: one per thread (construction builds OCCT's explorer of
// the solid, as BRepClass3d_SolidClassifier's does).
class SolidPointClassifier {
 public:
  explicit SolidPointClassifier(const TopoDS_Shape& solid);
  // IN, OUT or ON (see above), like BRepClass3d_SolidClassifier::Perform.
  TopAbs_State classify(const gp_Pnt& p, double tolerance);
  // Queries that OCCT's classifier answered (no clean ray).
  std::size_t fallbacks() const { return fallbacks_; }

 private:
  enum class RaySays { Clean, Unclean, On };
  RaySays cleanRay(const gp_Pnt& p, const gp_Dir& direction, double onReach, IntCurveSurface_TransitionOnCurve& first);
  bool grazes(const SolidRayCaster::Hit& hit, const gp_Dir& direction);

  BRepClass3d_SolidExplorer explorer_;
  BRepClass3d_SClassifier occt_;
  SolidRayCaster rays_;
  std::vector<SolidRayCaster::Hit> hits_;
  std::vector<std::unique_ptr<BRepAdaptor_Surface>> surfaces_;  // per face, for the normals at hits
  std::size_t fallbacks_ = 0;
  double diagonal_ = 0;  // of the solid's box: how far behind the point the rays start
  bool outsideIsOut_ = false;  // a clean ray from beyond the box entered the solid first
};

}  // namespace cadmedial
