// Rays through a solid's faces: the hits of IntCurvesFace_ShapeIntersector
// (every face's, sorted along the ray) at a fraction of its cost on parts
// with many faces.
//
// Why not the OCCT class itself (7.6): it intersects the ray with every
// face, and a plane or other analytic face hit outside its boundary
// rebuilds a 2D face classifier (BRepTopAdaptor_FClass2d) for that one
// answer whenever the face's edges have different tolerances: 60 % of the
// sampling time on the public gear (72 teeth). Here an analytic face (plane,
// cylinder, cone, sphere, torus) is asked only when the ray's line meets its
// bounding box (from its geometry, grown by its tolerances and the ray's;
// other faces reject the ray by their own polyhedron's box, as there), each
// face's intersector is built the first time it is asked, and a hit is kept
// when it lies in the face at zero UV
// tolerance (UseBToler off: the classifier is built once). The OCCT class
// also keeps hits up to its edges' tolerances outside the face; a ray that
// passes that close to an edge can miss a hit here (the thickness rays'
// fields came out byte-identical on 55 parts). With `nearEdgesToo`, hits
// are classified as the OCCT class does, up to the edges' tolerances, and
// such hits come out `onEdge` (SolidPointClassifier retries those rays).
#pragma once

#include <memory>
#include <vector>

#include <IntCurvesFace_Intersector.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Lin.hxx>

namespace cadmedial {

class SolidRayCaster {
 public:
  struct Hit {
    double w;     // parameter along the ray
    double u, v;  // on the face's surface
    int face;     // index into faces, in TopExp_Explorer order
    bool onEdge;  // on the face's boundary within its tolerance (state ON)
    IntCurveSurface_TransitionOnCurve transition;  // In: into the solid (face orientation applied)
  };

  // Every face of `shape` (TopExp_Explorer order, as the OCCT class loads
  // them), with `tolerance` for the intersections.
  SolidRayCaster(const TopoDS_Shape& shape, double tolerance, bool nearEdgesToo = false);
  // Shares the faces and boxes; builds its own intersectors (they are not
  // thread-safe): one copy per thread.
  SolidRayCaster(const SolidRayCaster& other);
  SolidRayCaster& operator=(const SolidRayCaster&) = delete;
  ~SolidRayCaster();

  // The hits with parameter in [wMin, wMax], sorted by parameter (ties in
  // face order). False when some face's intersection failed.
  bool cast(const gp_Lin& line, double wMin, double wMax, std::vector<Hit>& hits);
  const TopoDS_Face& face(int i) const;
  int faceCount() const;

 private:
  struct Shared;
  std::shared_ptr<const Shared> shared_;
  std::vector<std::unique_ptr<IntCurvesFace_Intersector>> intersectors_;  // per face, built on first use
};

}  // namespace cadmedial
