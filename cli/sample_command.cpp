#include "sample_command.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "atomic_file.hpp"
#include "cadmedial/brep_io.hpp"
#include "cadmedial/errors.hpp"
#include "cadmedial/sampling.hpp"
#include "ply_writers.hpp"
#include "report_json.hpp"

namespace cadmedial {

int runSampleCommand(const SampleCommandOptions& options) {
  const LoadedModel model = loadModel(options.model);
  for (const std::string& w : model.warnings) std::cerr << "warning: " << options.model << ": " << w << "\n";
  createOutputDirectory(options.outDir);

  std::printf("%-8s %9s %9s %7s %7s %8s %6s/%-6s %7s %8s %7s %8s\n", "solid", "samples", "triplets", "convex",
              "concave", "corners", "closed", "euler", "genus", "area%", "vol%", "seconds");
  for (std::size_t i = 0; i < model.solids.size(); ++i) {
    SamplingParams params;
    params.spacing = options.spacing;
    params.gradedSpacing = options.gradedSpacing;
    const SolidSampling result = sampleSolid(model.solids[i], params);
    const SamplingReport& r = result.report;
    const std::string dir = (std::filesystem::path(options.outDir) / ("solid_" + std::to_string(i))).string();
    createOutputDirectory(dir);
    writeFileAtomically(dir + "/samples.ply", [&](std::ofstream& out) { writeSamplesPly(out, result.samples); });
    writeFileAtomically(dir + "/boundary.ply", [&](std::ofstream& out) { writeBoundaryMeshPly(out, result.samples); });
    nlohmann::json summary = toJson(r);
    summary["model"] = options.model;
    summary["solid"] = i;
    summary["spacing"] = result.samples.spacing;
    summary["graded_spacing"] = options.gradedSpacing;
    writeFileAtomically(dir + "/sampling.json", [&](std::ofstream& out) { out << summary.dump(2) << "\n"; });

    const auto& f = r.features;
    const double seconds = r.secondsClassify + r.secondsSample + r.secondsReconstruct;
    std::printf("%-8zu %9zu %9zu %7d %7d %4d/%-3d %6s/%-6ld %7.2f %8.3f %7.3f %8.2f\n", i, result.samples.size(),
                r.triplets, f.convexEdges, f.concaveEdges, f.nonConcaveCorners, f.corners,
                r.surface.closedManifold() ? "yes" : "NO", r.surface.eulerCharacteristic, r.surface.genus(),
                100.0 * (r.surface.area / r.exactArea - 1.0), 100.0 * (r.surface.enclosedVolume / r.exactVolume - 1.0),
                seconds);
    for (const std::string& w : r.warnings) std::cerr << "warning: solid " << i << ": " << w << "\n";
  }
  std::printf("outputs in %s (per solid: samples.ply, boundary.ply, sampling.json)\n", options.outDir.c_str());
  return kExitOk;
}

}  // namespace cadmedial
