#include "cadmedial/cell_classification.hpp"

#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <BRepBndLib.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <Bnd_Box.hxx>

namespace cadmedial {

std::vector<std::uint8_t> classifyCellsBySolid(const DelaunayVoronoi& dv, const TopoDS_Shape& solid,
                                               double onTolerance) {
  std::vector<std::uint8_t> inner(dv.cellCount(), 0);
  Bnd_Box box;
  BRepBndLib::Add(solid, box);
  if (box.IsVoid()) return inner;
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  const double diagonal = std::sqrt(box.SquareExtent());
  tbb::enumerable_thread_specific<std::optional<BRepClass3d_SolidClassifier>> classifiers;
  tbb::parallel_for(tbb::blocked_range<Index>(0, static_cast<Index>(dv.cellCount()), 512),
                    [&](const tbb::blocked_range<Index>& range) {
                      auto& classifier = classifiers.local();
                      for (Index c = range.begin(); c != range.end(); ++c) {
                        if (dv.isInfinite(c) || !(dv.circumradius(c) <= diagonal)) continue;
                        const Vec3& p = dv.circumcenter(c);
                        if (p[0] < x0 || p[0] > x1 || p[1] < y0 || p[1] > y1 || p[2] < z0 || p[2] > z1) continue;
                        if (!classifier) classifier.emplace(solid);
                        classifier->Perform(gp_Pnt(p[0], p[1], p[2]), onTolerance);
                        inner[c] = classifier->State() == TopAbs_IN ? 1 : 0;
                      }
                    });
  return inner;
}

}  // namespace cadmedial
