#include "face_uv_classifier.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>

#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Precision.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>

namespace cadmedial {

namespace {

// Below this many inner wires the whole-face test checks few polygons, and
// building the per-wire copies costs more than it saves.
constexpr int kMinInnerWires = 4;

// Largest tolerance of the wire's edges, in UV: FClass2d calls a point ON
// within about this distance of an edge, so a wire's box grows by it.
double wireUVTolerance(const BRepAdaptor_Surface& surface, const TopoDS_Wire& wire) {
  double tol = 0;
  for (TopExp_Explorer ex(wire, TopAbs_EDGE); ex.More(); ex.Next())
    tol = std::max(tol, BRep_Tool::Tolerance(TopoDS::Edge(ex.Current())));
  return std::max(surface.UResolution(tol), surface.VResolution(tol));
}

// Whether x, shifted by a whole number of periods (none when period is 0),
// falls in [lo, hi].
bool inRange(double x, double lo, double hi, double period) {
  if (period <= 0) return x >= lo && x <= hi;
  const double shifted = x + std::ceil((lo - x) / period) * period;
  return shifted <= hi;
}

}  // namespace

FaceUVClassifier::FaceUVClassifier(const TopoDS_Face& face, double tolUV) {
  whole_ = std::make_unique<BRepTopAdaptor_FClass2d>(face, tolUV);

  // FClass2d classifies against the face taken FORWARD; so do the copies.
  const TopoDS_Face forward = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
  const TopoDS_Wire outer = BRepTools::OuterWire(forward);
  if (outer.IsNull()) return;
  std::vector<TopoDS_Wire> inner;
  for (TopExp_Explorer ex(forward, TopAbs_WIRE); ex.More(); ex.Next())
    if (!ex.Current().IsSame(outer)) inner.push_back(TopoDS::Wire(ex.Current()));
  if (static_cast<int>(inner.size()) < kMinInnerWires) return;

  const BRepAdaptor_Surface surface(forward, false);
  Bnd_Box2d outerBox;
  BRepTools::AddUVBounds(forward, outer, outerBox);
  if (outerBox.IsVoid()) return;
  std::vector<Bnd_Box2d> boxes(inner.size());
  for (std::size_t i = 0; i < inner.size(); ++i) {
    BRepTools::AddUVBounds(forward, inner[i], boxes[i]);
    // Not clearly a hole of the outer wire: keep the whole-face test.
    if (boxes[i].IsVoid() || outerBox.IsOut(boxes[i])) return;
    double u0, v0, u1, v1;
    boxes[i].Get(u0, v0, u1, v1);
    if (outerBox.IsOut(gp_Pnt2d(u0, v0)) || outerBox.IsOut(gp_Pnt2d(u1, v1))) return;
    // Enlarged well beyond the wire's ON band and its polygon's chords.
    const double size = std::hypot(u1 - u0, v1 - v0);
    boxes[i].Enlarge(0.05 * size + 10 * tolUV + 2 * wireUVTolerance(surface, inner[i]));
  }

  const BRep_Builder builder;
  auto faceWith = [&](const TopoDS_Wire* hole) {
    TopoDS_Face copy = TopoDS::Face(forward.EmptyCopied());
    {
      // Add also writes to the wire's shared TShape (it marks it not free,
      // which it already is), and other threads build classifiers from the
      // same wires (ExactOracle has one per thread).
      static std::mutex addMutex;
      const std::lock_guard<std::mutex> lock(addMutex);
      builder.Add(copy, outer);
      if (hole) builder.Add(copy, *hole);
    }
    return std::make_unique<BRepTopAdaptor_FClass2d>(copy, tolUV);
  };
  outerOnly_ = faceWith(nullptr);
  for (const TopoDS_Wire& hole : inner) outerAndInner_.push_back(faceWith(&hole));
  innerBoxes_ = std::move(boxes);
  uPeriod_ = surface.IsUPeriodic() ? surface.UPeriod() : 0;
  vPeriod_ = surface.IsVPeriodic() ? surface.VPeriod() : 0;
}

int FaceUVClassifier::innerWireAt(const gp_Pnt2d& uv) const {
  int found = -1;
  for (std::size_t i = 0; i < innerBoxes_.size(); ++i) {
    double u0, v0, u1, v1;
    innerBoxes_[i].Get(u0, v0, u1, v1);
    if (!inRange(uv.X(), u0, u1, uPeriod_) || !inRange(uv.Y(), v0, v1, vPeriod_)) continue;
    if (found >= 0) return -2;
    found = static_cast<int>(i);
  }
  return found;
}

TopAbs_State FaceUVClassifier::Perform(const gp_Pnt2d& uv) const {
  if (innerBoxes_.empty()) return whole_->Perform(uv);
  const int wire = innerWireAt(uv);
  if (wire == -1) return outerOnly_->Perform(uv);
  if (wire >= 0) return outerAndInner_[wire]->Perform(uv);
  return whole_->Perform(uv);
}

}  // namespace cadmedial
