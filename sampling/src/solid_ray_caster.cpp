#include "solid_ray_caster.hpp"

#include <algorithm>
#include <cmath>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

namespace cadmedial {

struct SolidRayCaster::Shared {
  std::vector<TopoDS_Face> faces;
  std::vector<Bnd_Box> boxes;
  double tolerance = 0;
  bool nearEdgesToo = false;
};

SolidRayCaster::SolidRayCaster(const TopoDS_Shape& shape, double tolerance, bool nearEdgesToo) {
  auto shared = std::make_shared<Shared>();
  shared->tolerance = tolerance;
  shared->nearEdgesToo = nearEdgesToo;
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
    const TopoDS_Face& face = TopoDS::Face(ex.Current());
    // A box from the geometry bounds a plane face (its edges' boxes) and a
    // cylinder, cone, sphere or torus patch (analytic bounds), grown by the
    // tolerances. Other surfaces (B-spline, Bezier, extrusion, revolution,
    // offset) get no box here: BndLib samples some of them, which can leave
    // a sliver of the face outside, and their intersector rejects a ray by
    // its own polyhedron's box first, as in the OCCT class.
    Bnd_Box box;
    const GeomAbs_SurfaceType type = BRepAdaptor_Surface(face, false).GetType();
    if (type == GeomAbs_Plane || type == GeomAbs_Cylinder || type == GeomAbs_Cone || type == GeomAbs_Sphere ||
        type == GeomAbs_Torus) {
      BRepBndLib::Add(face, box, false);
      if (!box.IsVoid()) box.Enlarge(2 * tolerance + 1e-9 * std::sqrt(box.SquareExtent()));
    }
    shared->faces.push_back(face);
    shared->boxes.push_back(box);
  }
  intersectors_.resize(shared->faces.size());
  shared_ = std::move(shared);
}

SolidRayCaster::SolidRayCaster(const SolidRayCaster& other)
    : shared_(other.shared_), intersectors_(other.shared_->faces.size()) {}

SolidRayCaster::~SolidRayCaster() = default;

bool SolidRayCaster::cast(const gp_Lin& line, double wMin, double wMax, std::vector<Hit>& hits) {
  hits.clear();
  const Shared& s = *shared_;
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    // A void box (no box made, or a face without geometry): asked.
    if (!s.boxes[f].IsVoid() && s.boxes[f].IsOut(line)) continue;
    std::unique_ptr<IntCurvesFace_Intersector>& mine = intersectors_[f];
    if (!mine) mine = std::make_unique<IntCurvesFace_Intersector>(s.faces[f], s.tolerance, true, s.nearEdgesToo);
    mine->Perform(line, wMin, wMax);
    if (!mine->IsDone()) return false;
    for (int k = 1; k <= mine->NbPnt(); ++k)
      hits.push_back({mine->WParameter(k), mine->UParameter(k), mine->VParameter(k), static_cast<int>(f),
                      mine->State(k) == TopAbs_ON, mine->Transition(k)});
  }
  std::stable_sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) { return a.w < b.w; });
  return true;
}

const TopoDS_Face& SolidRayCaster::face(int i) const { return shared_->faces[static_cast<std::size_t>(i)]; }

int SolidRayCaster::faceCount() const { return static_cast<int>(shared_->faces.size()); }

}  // namespace cadmedial
