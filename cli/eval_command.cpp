// CGAL (core) headers before OCCT's.
#include "pair_mesh_stage.hpp"
#include "eval_command.hpp"

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <vector>

#include "atomic_file.hpp"
#include "cadmedial/brep_io.hpp"
#include "cadmedial/errors.hpp"
#include "medial_ply_io.hpp"
#include "pair_mesh_io.hpp"

namespace cadmedial {

namespace {

std::string solidDir(const std::string& outDir, std::size_t i) {
  return (std::filesystem::path(outDir) / ("solid_" + std::to_string(i))).string();
}

// Names of the failed checks, or "PASS".
std::string verdictText(const EvaluationVerdict& v) {
  std::string failed;
  auto add = [&](bool ok, const char* name) {
    if (!ok) failed += (failed.empty() ? "" : ",") + std::string(name);
  };
  add(v.inside, "inside");
  add(v.medialness, "medial");
  add(v.twoContacts, "contacts");
  add(v.coverage, "coverage");
  add(v.edges, "edges");
  add(v.corners, "corners");
  add(v.topology, "topology");
  return failed.empty() ? "PASS" : "FAIL:" + failed;
}

}  // namespace

nlohmann::json toJson(const EvaluationReport& r) {
  using nlohmann::json;
  const EvaluationThresholds& th = r.params.thresholds;
  json j;
  j["diagonal"] = r.diagonal;
  j["tolerance"] = r.tolerance;
  j["tolerance_fraction"] = r.params.toleranceFraction;
  j["mesh"] = {{"vertices", r.vertices}, {"unused_vertices", r.unusedVertices}, {"polygons", r.polygons},
               {"sheets", r.sheets}};
  j["inside"] = {{"share", r.inside.share},         {"area", r.inside.area},
                 {"outside_area", r.inside.outsideArea}, {"triangles", r.inside.triangles},
                 {"points", r.inside.points},       {"outside_points", r.inside.outsidePoints},
                 {"max_outside_depth", r.inside.maxOutsideDepth}};
  j["medialness"] = {{"vertices", r.medialness.vertices},
                     {"median", r.medialness.median},
                     {"p90", r.medialness.p90},
                     {"max", r.medialness.max},
                     {"relative_to", "diagonal"},
                     {"two_contacts", r.medialness.twoContacts},
                     {"two_contact_share", r.medialness.twoContactShare},
                     {"contact_angle_deg", r.params.contactAngleDeg}};
  // An infinite gap (no medial vertex at all) is written as null.
  j["coverage"] = {{"points", r.coverage.points},
                   {"covered", r.coverage.covered},
                   {"share", r.coverage.share},
                   {"max_gap", std::isfinite(r.coverage.maxGap) ? json(r.coverage.maxGap) : json(nullptr)}};
  // edge_share is over the steep length (creases turning by >= 2θ); the
  // shallow length, which the θ-filtered axis leaves by design, is reported apart.
  j["attachment"] = {{"convex_edges", r.attachment.convexEdges},
                     {"convex_length", r.attachment.convexLength},
                     {"steep_length", r.attachment.steepLength},
                     {"attached_length", r.attachment.attachedLength},
                     {"edge_share", r.attachment.edgeShare},
                     {"shallow_below_deg", 2 * r.params.thetaDeg},
                     {"shallow_length", r.attachment.shallowLength},
                     {"shallow_attached_length", r.attachment.shallowAttachedLength},
                     {"corners", r.attachment.corners},
                     {"attached_corners", r.attachment.attachedCorners},
                     {"corner_share", r.attachment.cornerShare},
                     {"shallow_corners", r.attachment.shallowCorners},
                     {"shallow_attached_corners", r.attachment.shallowAttachedCorners}};
  const TopologyMetric& t = r.topology;
  j["topology"] = {{"medial", {{"vertices", t.vertices},
                               {"edges", t.edges},
                               {"polygons", t.polygons},
                               {"core_polygons", t.corePolygons},
                               {"euler", t.euler},
                               {"beta0", t.beta0},
                               {"beta1", t.beta1},
                               {"beta2", t.beta2}}},
                   {"solid", {{"shells", t.shells}, {"beta0", t.solidBeta0}, {"beta1", t.solidBeta1}, {"beta2", t.solidBeta2}}},
                   {"matches", t.matches}};
  j["thresholds"] = {{"min_inside_share", th.minInsideShare},
                     {"max_medialness_median_tol", th.maxMedialnessMedianTol},
                     {"max_medialness_p90_tol", th.maxMedialnessP90Tol},
                     {"min_two_contact_share", th.minTwoContactShare},
                     {"min_coverage", th.minCoverage},
                     {"min_edge_attachment", th.minEdgeAttachment},
                     {"min_corner_attachment", th.minCornerAttachment}};
  const EvaluationVerdict& v = r.pass;
  j["pass"] = {{"inside", v.inside},   {"medialness", v.medialness}, {"two_contacts", v.twoContacts},
               {"coverage", v.coverage}, {"edges", v.edges},         {"corners", v.corners},
               {"topology", v.topology}, {"all", v.all()}};
  j["seconds"] = {{"setup", r.secondsSetup},         {"inside", r.secondsInside},
                  {"medialness", r.secondsMedialness}, {"coverage", r.secondsCoverage},
                  {"attachment", r.secondsAttachment}, {"topology", r.secondsTopology}};
  return j;
}

void printEvaluationHeader(std::FILE* out) {
  std::fprintf(out, "%-6s %8s %22s %9s %8s %8s %8s %15s  %s\n", "solid", "inside%", "|d-r|/diag% med/p90/max",
               "2-touch%", "cover%", "edges%", "corners", "b0,b1 (solid)", "verdict");
}

void printEvaluationRow(std::FILE* out, const std::string& solid, const EvaluationReport& r) {
  char medial[64], corners[32], betti[48];
  std::snprintf(medial, sizeof medial, "%.3f/%.3f/%.3f", 100 * r.medialness.median, 100 * r.medialness.p90,
                100 * r.medialness.max);
  std::snprintf(corners, sizeof corners, "%d/%d", r.attachment.attachedCorners, r.attachment.corners);
  std::snprintf(betti, sizeof betti, "%lld,%lld (%lld,%lld)", r.topology.beta0, r.topology.beta1,
                r.topology.solidBeta0, r.topology.solidBeta1);
  std::fprintf(out, "%-6s %8.2f %22s %9.2f %8.2f %8.2f %8s %15s  %s\n", solid.c_str(), 100 * r.inside.share, medial,
               100 * r.medialness.twoContactShare, 100 * r.coverage.share, 100 * r.attachment.edgeShare, corners, betti,
               verdictText(r.pass).c_str());
}

namespace {

// The convex length that edges% leaves out, when there is some.
void printShallowCreases(std::FILE* out, const EvaluationReport& r) {
  const AttachmentMetric& a = r.attachment;
  if (!(a.shallowLength > 0) && a.shallowCorners == 0) return;
  std::fprintf(out,
               "       shallow creases (turning < %g deg = 2 theta, which the Angle condition cannot see; "
               "not in edges%% or corners): %.4g of %.4g convex length, %.1f %% attached; %d/%d corners\n",
               2 * r.params.thetaDeg, a.shallowLength, a.convexLength,
               a.shallowLength > 0 ? 100 * a.shallowAttachedLength / a.shallowLength : 100.0, a.shallowAttachedCorners,
               a.shallowCorners);
}

// The θ that a CAD_MEDIAL `run` used for this solid (summary.json), if it
// says. Not MEDIAL's (point clouds, 22.5° by default): its creases below 45°
// would be left out, and its figures would no longer compare with
// CAD_MEDIAL's on the same solid (bench/medial_vs_cad.py).
std::optional<double> runTheta(const std::string& dir) {
  std::ifstream in(dir + "/summary.json");
  if (!in) return std::nullopt;
  const nlohmann::json summary = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  const nlohmann::json::json_pointer at("/parameters/theta_deg");
  if (summary.is_discarded() || summary.value("algorithm", "") != "CAD_MEDIAL" || !summary.contains(at) ||
      !summary.at(at).is_number())
    return std::nullopt;
  const double theta = summary.at(at).get<double>();
  return theta >= 0 && theta < 90 ? std::optional<double>(theta) : std::nullopt;
}

// OUTDIR must hold what `run` made of this model: eval would otherwise
// measure another solid's axis against this one and overwrite its eval.json.
// `run` records each solid's exact volume and area in summary.json; they
// must agree to 1e-6 (BRepGProp on the same B-rep gives the same numbers).
// Outputs without that record (point-cloud runs, older outputs) are not
// checked. (Extra solid_<k> folders are not refused: `run` leaves those of
// an earlier run into the same OUTDIR in place.)
void checkOutputsAreOfThisModel(const EvalCommandOptions& options, const LoadedModel& model) {
  for (std::size_t i = 0; i < model.solids.size(); ++i) {
    std::ifstream in(solidDir(options.outDir, i) + "/summary.json");
    if (!in) continue;
    const nlohmann::json summary = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    const nlohmann::json::json_pointer volumeAt("/sampling/reconstruction/exact_volume"),
        areaAt("/sampling/reconstruction/exact_area");
    if (summary.is_discarded() || !summary.contains(volumeAt) || !summary.contains(areaAt) ||
        !summary.at(volumeAt).is_number() || !summary.at(areaAt).is_number())
      continue;
    GProp_GProps volume, area;
    BRepGProp::VolumeProperties(model.solids[i], volume);
    BRepGProp::SurfaceProperties(model.solids[i], area);
    auto differ = [](double a, double b) { return std::abs(a - b) > 1e-6 * std::max(std::abs(a), std::abs(b)); };
    const double runVolume = summary.at(volumeAt).get<double>(), runArea = summary.at(areaAt).get<double>();
    if (differ(runVolume, volume.Mass()) || differ(runArea, area.Mass())) {
      char numbers[160];
      std::snprintf(numbers, sizeof numbers, "volume %.6g, area %.6g there; %.6g and %.6g here", runVolume, runArea,
                    volume.Mass(), area.Mass());
      throw InputError(kExitUsage, solidDir(options.outDir, i) + " was computed from another solid than solid " +
                                       std::to_string(i) + " of " + options.model + " (" + numbers +
                                       "): give `eval` the model that `run` was given");
    }
  }
}

}  // namespace

int runEvalCommand(const EvalCommandOptions& options) {
  if (!(options.tolerance > 0 && options.tolerance < 1))
    throw InputError(kExitUsage, "--tolerance must be a fraction of the diagonal in (0, 1)");
  const LoadedModel model = loadModel(options.model);
  for (const std::string& w : model.warnings) std::cerr << "warning: " << options.model << ": " << w << "\n";

  // Every input is checked before any (slow) evaluation starts.
  std::vector<std::string> plyPaths;
  for (std::size_t i = 0; i < model.solids.size(); ++i) {
    plyPaths.push_back(solidDir(options.outDir, i) + "/medial.ply");
    if (!std::filesystem::is_regular_file(plyPaths.back()))
      throw InputError(kExitUnreadableInput, "missing " + plyPaths.back() + " (write it with `cadmedial run " +
                                                 options.model + " -o " + options.outDir + "`)");
  }

  checkOutputsAreOfThisModel(options, model);

  if (!options.quiet) printEvaluationHeader(stdout);
  bool allPass = true;
  for (std::size_t i = 0; i < model.solids.size(); ++i) {
    EvaluationParams params;
    params.toleranceFraction = options.tolerance;
    params.thetaDeg = runTheta(solidDir(options.outDir, i)).value_or(params.thetaDeg);
    const MedialMesh mesh = readMedialPlyFile(plyPaths[i]);
    const EvaluationReport report = evaluateMedial(model.solids[i], mesh, params);
    nlohmann::json j = toJson(report);
    j["model"] = options.model;
    j["solid"] = i;
    j["medial_ply"] = plyPaths[i];
    // The pair-mesh, when `run --pair-mesh` wrote one: read back and checked
    // here, independently of what run reported.
    const std::string pairBase = solidDir(options.outDir, i) + "/pairmesh";
    bool pairPass = true;
    if (std::filesystem::is_regular_file(pairBase + ".ele")) {
      const PairMesh pairMesh = readPairMeshTetgen(pairBase);
      j["pair_mesh"] = pairMeshReport(pairMesh, model.solids[i]);
      // The iso-surface halfway between axis and boundary must not cut itself.
      // Exact surface; the written (rounded) points may show crossings of sliver cuts.
      const IsoSurfaceIntersections iso = isoSurfaceSelfIntersections(isoSurface(pairMesh, 0.5), pairMesh);
      j["pair_mesh"]["iso_0.5_rounded_crossings"] = iso.roundedCrossings;
      j["pair_mesh"]["iso_0.5_self_intersections"] = iso.intersectingPairs;
      j["pair_mesh"]["iso_0.5_degenerate_triangles"] = iso.degenerateTriangles;
      j["pair_mesh"]["iso_0.5_crossing_elements"] = iso.elementPairs;  // element ids in pairmesh.ele
      pairPass = j["pair_mesh"]["pass"].get<bool>() && iso.intersectingPairs == 0;
      j["pair_mesh"]["pass"] = pairPass;
    }
    writeFileAtomically(solidDir(options.outDir, i) + "/eval.json", [&](std::ofstream& out) { out << j.dump(2) << "\n"; });
    if (!options.quiet) {
      printEvaluationRow(stdout, std::to_string(i), report);
      printShallowCreases(stdout, report);
      if (j.contains("pair_mesh")) {
        const auto& pm = j["pair_mesh"];
        std::printf("       pair-mesh: %zu tetrahedra, %zu inverted, overlap %.1e, gap %.1e, volume %.6g vs exact %.6g "
                    "(%.3f %%), iso 0.5 self-intersections %zu  %s\n",
                    pm["tetrahedra"].get<std::size_t>(), pm["inverted"].get<std::size_t>(),
                    pm["overlap_error"].get<double>(), pm["gap_error"].get<double>(),
                    pm["enclosed_volume"].get<double>(), pm["exact_volume"].get<double>(),
                    pm["volume_error"].is_null() ? NAN : 100 * pm["volume_error"].get<double>(),
                    pm["iso_0.5_self_intersections"].get<std::size_t>(), pairPass ? "PASS" : "FAIL");
      }
      std::fflush(stdout);
    }
    allPass = allPass && report.pass.all() && pairPass;
  }
  if (!options.quiet) std::printf("per solid: eval.json in %s/solid_<i>/\n", options.outDir.c_str());
  return options.strict && !allPass ? kExitProcessingFailed : kExitOk;
}

}  // namespace cadmedial
