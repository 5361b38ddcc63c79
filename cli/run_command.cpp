// CGAL headers must come before OCCT's: OCCT defines a `Handle` macro that
// breaks CGAL's own `Handle` templates.
#include "cadmedial/medial.hpp"
#include "run_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <tbb/parallel_invoke.h>

#include "atomic_file.hpp"
#include "cadmedial/brep_io.hpp"
#include "cadmedial/errors.hpp"
#include "cadmedial/sampling.hpp"
#include "medial_outputs.hpp"
#include "pair_mesh_stage.hpp"
#include "solid_run.hpp"
#include "topology_check.hpp"
#include "medial_summary.hpp"
#include "point_input.hpp"
#include "run_points_command.hpp"
#include "report_json.hpp"

namespace cadmedial {

namespace {
using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// One line when the pair-mesh was not valid at the spacing asked and the
// solid was sampled again (solid_run.hpp).
void printResampling(const nlohmann::json& attempts) {
  const std::string line = resamplingLine(attempts);
  if (!line.empty()) std::printf("       pair-mesh: %s\n", line.c_str());
}
}  // namespace

int runRunCommand(const RunCommandOptions& options) {
  if (isPointInputPath(options.model)) {
    if (options.pairMesh) std::cerr << "warning: --pair-mesh needs a B-rep solid; ignored for " << options.model << "\n";
    return runPointMedialCommand(options);
  }
  auto t = Clock::now();
  LoadedModel model;
  try {
    model = loadModel(options.model);
  } catch (const InputError& e) {
    // `run` also takes point clouds and meshes: say so where the B-rep reader
    // lists only its own extensions.
    std::string message = e.what();
    if (message.find("unknown extension") != std::string::npos)
      message.insert(message.rfind(')'), ", or a point cloud / mesh: .xyz .pts .ply .stl .obj .off");
    throw InputError(e.code(), message);
  }
  const double secondsRead = secondsSince(t);
  for (const std::string& w : model.warnings) std::cerr << "warning: " << options.model << ": " << w << "\n";
  createOutputDirectory(options.outDir);

  std::printf("%-6s %8s %9s %9s %8s %7s %6s %6s %9s %8s\n", "solid", "samples", "cells", "polygons", "sheets", "b0/b1",
              "walk", "oracle", "notDelny", "seconds");
  for (std::size_t i = 0; i < model.solids.size(); ++i) {
    SamplingParams sampling;
    sampling.spacing = options.spacing;
    sampling.gradedSpacing = options.gradedSpacing;
    const auto solidStart = Clock::now();
    MedialParams params = options.params;
    params.computeTopology = false;  // below, while the files are written
    SolidResult run = runSolid(model.solids[i], sampling, params, options.checkWithOracle, options.pairMesh);
    const SolidSampling& sampled = run.sampled;
    MedialResult& medial = run.medial;

    t = Clock::now();
    const std::string dir = (std::filesystem::path(options.outDir) / ("solid_" + std::to_string(i))).string();
    createOutputDirectory(dir);
    // Writing is mostly the kernel copying text into files (~1.2 cores busy
    // at 10^6 samples): the Betti numbers for the summary fit beside it.
    double secondsTopology = 0;
    tbb::parallel_invoke([&] { writeMedialFiles(dir, medial); },
                         [&] {
                           const auto start = Clock::now();
                           medial.topology = computeTopology(medial, medial.edges, params.bettiCoreLimit);
                           secondsTopology = secondsSince(start);
                         });
    medial.times.topology = secondsTopology;
    const double secondsWrite = secondsSince(t);

    nlohmann::json summary = medialSummaryJson(sampled.report, medial, options.params);
    if (options.pairMesh) {
      writePairMeshFiles(*run.pairMesh, options.isoValues, dir);
      summary["pair_mesh"] = run.pairMesh->report;
      const auto& pm = summary["pair_mesh"];
      std::printf("       pair-mesh: %zu tetrahedra, %zu inverted, volume error %.3g %%, %s\n",
                  pm["tetrahedra"].get<std::size_t>(), pm["inverted"].get<std::size_t>(),
                  pm["volume_error"].is_null() ? NAN : 100 * pm["volume_error"].get<double>(),
                  pm["pass"].get<bool>() ? "valid" : "NOT VALID");
      printResampling(pm["attempts"]);
    }
    summary["model"] = options.model;
    summary["solid"] = i;
    summary["spacing"] = sampled.samples.spacing;
    summary["graded_spacing"] = options.gradedSpacing;
    summary["seconds"]["read"] = secondsRead;
    summary["seconds"]["write"] = secondsWrite;
    // Wall time from the file read to this solid's outputs: the stages
    // overlap (the triangulation runs alongside the reconstruction and the
    // preparation), so their sum is more.
    const double seconds = secondsRead + secondsSince(solidStart);
    summary["seconds"]["end_to_end"] = seconds;
    const std::string topologyWarning =
        recordSolidTopology(summary, model.solids[i], medial.topology, sampled.samples.spacing);
    writeFileAtomically(dir + "/summary.json", [&](std::ofstream& out) { out << summary.dump(2) << "\n"; });

    char betti[32];
    std::snprintf(betti, sizeof betti, "%lld/%lld", medial.topology.beta0, medial.topology.beta1);
    std::printf("%-6zu %8zu %9zu %9zu %8zu %7s %6zu %6zu %9zu %8.2f\n", i, sampled.samples.size(),
                medial.counts.delaunayCells, medial.polygonCount(), medial.sheetCount, betti,
                medial.counts.oracleChecked, medial.counts.oracleDisagreements, medial.counts.tripletsNotDelaunay,
                seconds);
    for (const std::string& w : sampled.report.warnings) std::cerr << "warning: solid " << i << ": " << w << "\n";
    if (!topologyWarning.empty()) std::cerr << "warning: solid " << i << ": " << topologyWarning << "\n";
  }
  std::printf("outputs in %s (per solid: medial.ply, medial.obj, medial.ma, summary.json%s)\n", options.outDir.c_str(),
              options.pairMesh ? ", pairmesh.vtu, pairmesh.node/.ele, iso_<t>.ply" : "");
  return kExitOk;
}

}  // namespace cadmedial
