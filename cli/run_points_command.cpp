// CGAL headers first (OCCT's Handle macro; see run_command.cpp).
#include "cadmedial/compute_medial.hpp"
#include "run_points_command.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "atomic_file.hpp"
#include "cadmedial/errors.hpp"
#include "medial_outputs.hpp"
#include "medial_summary.hpp"
#include "point_input.hpp"

namespace cadmedial {

namespace {
using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
}  // namespace

int runPointMedialCommand(const RunCommandOptions& options) {
  auto t = Clock::now();
  const PointInput input = readPointInput(options.model);
  const double secondsRead = secondsSince(t);
  for (const std::string& w : input.warnings) std::cerr << "warning: " << options.model << ": " << w << "\n";
  if (options.spacing > 0) std::cerr << "warning: --spacing is ignored for point clouds and meshes (the points are the samples)\n";

  MedialParams params = options.params;
  if (!options.thetaGiven) params.thetaDeg = MedialParams::pointCloud().thetaDeg;
  const PointMedialResult medial = computeMedial(input.points, params, input.triangles);

  t = Clock::now();
  const std::string dir = (std::filesystem::path(options.outDir) / "solid_0").string();
  createOutputDirectory(dir);
  writeMedialFiles(dir, medial);
  const double secondsWrite = secondsSince(t);

  nlohmann::json summary = pointMedialSummaryJson(input, medial, params);
  summary["model"] = options.model;
  summary["solid"] = 0;
  summary["seconds"]["read"] = secondsRead;
  summary["seconds"]["write"] = secondsWrite;
  writeFileAtomically(dir + "/summary.json", [&](std::ofstream& out) { out << summary.dump(2) << "\n"; });

  std::printf("%-6s %8s %9s %9s %8s %7s %6s %8s\n", "input", "points", "cells", "polygons", "sheets", "b0/b1",
              "axis", "seconds");
  char betti[32];
  std::snprintf(betti, sizeof betti, "%lld/%lld", medial.topology.beta0, medial.topology.beta1);
  std::printf("%-6s %8zu %9zu %9zu %8zu %7s %6s %8.2f\n", input.format.c_str(), input.points.size(),
              medial.counts.delaunayCells, medial.polygonCount(), medial.sheetCount, betti,
              medial.cloud.part == MedialAxisPart::Inner ? "inner" : "whole", medial.times.total + secondsWrite);
  std::printf("MEDIAL (theta %.4g deg, rho %.4g): %s\n", params.thetaDeg, params.rho, medial.cloud.axisNote.c_str());
  std::printf("outputs in %s (medial.ply, medial.obj, medial.ma, summary.json)\n", dir.c_str());
  return kExitOk;
}

}  // namespace cadmedial
