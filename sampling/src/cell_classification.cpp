// CGAL (core) headers before OCCT's.
#include "cadmedial/cell_sides.hpp"
#include "cadmedial/surface_mesh_checks.hpp"
#include "cadmedial/cell_classification.hpp"

#include <atomic>
#include <cmath>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <BRepBndLib.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <Bnd_Box.hxx>

namespace cadmedial {

CellClassification classifyCellsBySolid(const DelaunayVoronoi& dv, const TopoDS_Shape& solid, const SampleSet* samples,
                                        double band, double onTolerance) {
  CellClassification out;
  out.inner.assign(dv.cellCount(), 0);
  Bnd_Box box;
  BRepBndLib::Add(solid, box);
  if (box.IsVoid()) return out;
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  const double diagonal = std::sqrt(box.SquareExtent());

  // Side of the reconstruction where it is closed and the centre is far from it.
  std::vector<std::uint8_t> meshSide;
  if (samples && band > 0 && !samples->triangles.empty() &&
      checkSurfaceMesh(samples->points, samples->triangles).closedManifold())
    meshSide = classifyCellSides(dv, *samples, {}, band, nullptr, true);

  std::atomic<std::size_t> exact{0}, byMesh{0};
  tbb::enumerable_thread_specific<std::optional<BRepClass3d_SolidClassifier>> classifiers;
  tbb::parallel_for(tbb::blocked_range<Index>(0, static_cast<Index>(dv.cellCount()), 512),
                    [&](const tbb::blocked_range<Index>& range) {
                      auto& classifier = classifiers.local();
                      std::size_t queries = 0, decided = 0;
                      for (Index c = range.begin(); c != range.end(); ++c) {
                        if (dv.isInfinite(c) || !(dv.circumradius(c) <= diagonal)) continue;
                        const Vec3& p = dv.circumcenter(c);
                        if (p[0] < x0 || p[0] > x1 || p[1] < y0 || p[1] > y1 || p[2] < z0 || p[2] > z1) continue;
                        if (!meshSide.empty() && (meshSide[c] == kCellInside || meshSide[c] == kCellOutside)) {
                          out.inner[c] = meshSide[c] == kCellInside ? 1 : 0;
                          ++decided;
                          continue;
                        }
                        if (!classifier) classifier.emplace(solid);
                        classifier->Perform(gp_Pnt(p[0], p[1], p[2]), onTolerance);
                        out.inner[c] = classifier->State() == TopAbs_IN ? 1 : 0;
                        ++queries;
                      }
                      exact += queries;
                      byMesh += decided;
                    });
  out.exactQueries = exact;
  out.decidedByMesh = byMesh;
  return out;
}

}  // namespace cadmedial
