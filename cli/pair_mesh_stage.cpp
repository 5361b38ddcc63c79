#include "pair_mesh_stage.hpp"

#include <chrono>
#include <cmath>

#include <tbb/parallel_invoke.h>

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>

#include "cadmedial/cell_classification.hpp"
#include "pair_mesh_io.hpp"

namespace cadmedial {

namespace {
using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
}  // namespace

nlohmann::json pairMeshReport(const PairMesh& mesh, const TopoDS_Shape& solid) {
  const PairMeshValidity v = checkPairMesh(mesh);
  GProp_GProps props;
  BRepGProp::VolumeProperties(solid, props);
  const double exact = std::abs(props.Mass());
  const double volumeError = exact > 0 ? std::abs(v.enclosedVolume - exact) / exact : INFINITY;
  std::size_t perType[3] = {0, 0, 0}, onSheets = 0;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    ++perType[static_cast<int>(mesh.type[i])];
    onSheets += mesh.onSheets[i];
  }
  const bool volumeOk = volumeError <= kPairMeshVolumeTolerance;
  return {{"tetrahedra", mesh.size()},
          {"face_vertex", perType[0]},
          {"edge_edge", perType[1]},
          {"vertex_face", perType[2]},
          {"nodes", mesh.nodes.size()},
          {"boundary_triangles", v.boundaryTriangles},
          {"inverted", v.inverted},
          {"degenerate", v.degenerate},
          {"overlap_error", v.overlapError},
          {"gap_error", v.gapError},
          {"boundary_triangles_not_in_one_vertex_face", v.boundaryTrianglesNotInOneVertexFace},
          {"boundary_edges_not_shared", v.boundaryEdgesNotShared},
          {"enclosed_volume", v.enclosedVolume},
          {"exact_volume", exact},
          {"volume_error", std::isfinite(volumeError) ? nlohmann::json(volumeError) : nlohmann::json(nullptr)},
          {"valid", v.valid()},
          {"pass", v.valid() && volumeOk}};
}

PairMeshStage buildPairMeshStage(const DelaunayVoronoi& dv, const SampleSet& samples, const TopoDS_Shape& solid,
                                 const MedialComplex& axis, const CellSideInputs* prepared) {
  PairMeshStage stage;
  auto t = Clock::now();
  // Centres farther from every reconstruction triangle than its measured
  // deviation from the exact surface take the reconstruction's side; the
  // rest go to OCCT's classifier (h/2 is the band only for sample sets
  // without triangleDeviation).
  const CellClassification cells = classifyCellsBySolid(dv, solid, &samples, 0.5 * samples.spacing, 1e-9, prepared);
  const double classifySeconds = secondsSince(t);
  stage.mesh = buildPairMesh(dv, samples, cells.inner, &axis);
  const PairMesh& mesh = stage.mesh;
  t = Clock::now();
  nlohmann::json& report = stage.report;
  report = pairMeshReport(mesh, solid);
  const double checkSeconds = secondsSince(t);
  report["on_sheets"] = std::count(mesh.onSheets.begin(), mesh.onSheets.end(), 1);
  report["cells_classified_exactly"] = cells.exactQueries;
  report["cells_decided_by_reconstruction"] = cells.decidedByMesh;
  report["reconstruction_ray_casts"] = cells.rayCasts;
  report["reconstruction_segment_tests"] = cells.segmentTests;
  report["inverted_before_repair"] = mesh.counts.invertedBeforeRepair;
  report["moved_voronoi_nodes"] = mesh.counts.movedNodes;
  report["welded_voronoi_nodes"] = mesh.counts.weldedNodes;
  report["split_boundary_edges"] = mesh.counts.splitEdges;
  report["retriangulated_voronoi_polygons"] = mesh.counts.retriangulatedPolygons;
  report["relabelled_flat_cells"] = mesh.counts.relabelledFlatCells;
  report["relabelled_boundary_cells"] = mesh.counts.relabelledBoundaryCells;
  report["inverted_after_repair"] = mesh.counts.invertedAfterRepair;
  report["seconds"] = {{"classify_cells", classifySeconds},
                       {"classify_cells_near_test", cells.nearSeconds},
                       {"classify_cells_links", cells.linkSeconds},
                       {"classify_cells_rays", cells.raySeconds},
                       {"build", mesh.seconds},
                       {"repair", mesh.repairSeconds},
                       {"check", checkSeconds},
                       {"total", classifySeconds + mesh.seconds + mesh.repairSeconds + checkSeconds}};
  return stage;
}

void writePairMeshFiles(PairMeshStage& stage, const std::vector<double>& isoValues, const std::string& dir) {
  const PairMesh& mesh = stage.mesh;
  nlohmann::json& report = stage.report;
  const auto t = Clock::now();
  std::vector<std::string> isoFiles;
  tbb::parallel_invoke([&] { writePairMeshVtu(dir + "/pairmesh.vtu", mesh); },
                       [&] { writePairMeshTetgen(dir + "/pairmesh", mesh); },
                       [&] {
                         for (double iso : isoValues)
                           writeIsoSurfacePly(dir + "/" + isoSurfaceFileName(iso), isoSurface(mesh, iso));
                       });
  for (double iso : isoValues) isoFiles.push_back(isoSurfaceFileName(iso));
  report["iso_files"] = isoFiles;
  report["seconds"]["write"] = secondsSince(t);
}

}  // namespace cadmedial
