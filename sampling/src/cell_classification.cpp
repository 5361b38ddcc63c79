// CGAL (core) headers before OCCT's.
#include "cadmedial/reconstruction_sides.hpp"
#include "cadmedial/surface_mesh_checks.hpp"
#include "cadmedial/cell_classification.hpp"

#include <atomic>
#include <cmath>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>

#include "solid_point_classifier.hpp"

namespace cadmedial {

CellClassification classifyCellsBySolid(const DelaunayVoronoi& dv, const TopoDS_Shape& solid, const SampleSet* samples,
                                        double band, double onTolerance, const CellSideInputs* prepared) {
  CellClassification out;
  out.inner.assign(dv.cellCount(), 0);
  Bnd_Box box;
  BRepBndLib::Add(solid, box);
  if (box.IsVoid()) return out;
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  const double diagonal = std::sqrt(box.SquareExtent());

  // Cells that need an answer: the others are outer without one.
  std::vector<std::uint8_t> wanted(dv.cellCount(), 0);
  for (Index c = 0; c < dv.cellCount(); ++c) {
    if (dv.isInfinite(c) || !(dv.circumradius(c) <= diagonal)) continue;
    const Vec3& p = dv.circumcenter(c);
    wanted[c] = !(p[0] < x0 || p[0] > x1 || p[1] < y0 || p[1] > y1 || p[2] < z0 || p[2] > z1);
  }
  // Side of the reconstruction where it is closed and the centre is farther
  // from each triangle than that triangle's deviation from the exact surface
  // (SampleSet::triangleDeviation, else the uniform band).
  // (The prepared inputs hold a tree exactly when the reconstruction is
  // closed and manifold: the same check.)
  std::vector<std::uint8_t> meshSide;
  if (samples && !samples->triangles.empty() &&
      (band > 0 || samples->triangleDeviation.size() == samples->triangles.size()) &&
      (prepared ? prepared->mesh != nullptr : checkSurfaceMesh(samples->points, samples->triangles).closedManifold())) {
    const std::vector<double> deviation = samples->triangleDeviation.size() == samples->triangles.size()
                                              ? samples->triangleDeviation
                                              : std::vector<double>(samples->triangles.size(), band);
    ReconstructionSides sides = prepared ? reconstructionSides(dv, *prepared, deviation, &wanted)
                                         : reconstructionSides(dv, *samples, deviation, &wanted);
    out.rayCasts = sides.rayCasts;
    out.segmentTests = sides.segmentTests;
    out.nearSeconds = sides.nearSeconds;
    out.linkSeconds = sides.linkSeconds;
    out.raySeconds = sides.raySeconds;
    meshSide = std::move(sides.side);
  }

  std::atomic<std::size_t> exact{0}, byMesh{0};
  tbb::enumerable_thread_specific<std::optional<SolidPointClassifier>> classifiers;
  tbb::parallel_for(tbb::blocked_range<Index>(0, static_cast<Index>(dv.cellCount()), 512),
                    [&](const tbb::blocked_range<Index>& range) {
                      auto& classifier = classifiers.local();
                      std::size_t queries = 0, decided = 0;
                      for (Index c = range.begin(); c != range.end(); ++c) {
                        if (!wanted[c]) continue;
                        const Vec3& p = dv.circumcenter(c);
                        if (!meshSide.empty() &&
                            (meshSide[c] == kReconstructionInside || meshSide[c] == kReconstructionOutside)) {
                          out.inner[c] = meshSide[c] == kReconstructionInside ? 1 : 0;
                          ++decided;
                          continue;
                        }
                        if (!classifier) classifier.emplace(solid);
                        out.inner[c] = classifier->classify(gp_Pnt(p[0], p[1], p[2]), onTolerance) == TopAbs_IN;
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
