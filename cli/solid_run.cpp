#include "solid_run.hpp"

#include <chrono>
#include <optional>
#include <string>

#include <BRepClass3d_SolidClassifier.hxx>
#include <Standard_Failure.hxx>

namespace cadmedial {

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void call(const std::function<void(const char*)>& stage, const char* name) {
  if (stage) stage(name);
}

// One sampling at `sampling` through the axis and, when asked, the pair-mesh.
SolidResult attempt(const TopoDS_Shape& solid, const SamplingParams& sampling, const MedialParams& params,
                 bool withOracle, bool pairMesh, const std::function<void(const char*)>& stage) {
  SolidResult run;
  call(stage, "sample");
  const auto start = Clock::now();
  // Local: the triangulation and the prepared samples are freed when this
  // attempt ends, so a sampling again does not hold two of them at once.
  TriangulatedSamples triangulated = sampleAndTriangulate(solid, sampling, params.mayReadCellSides());
  call(stage, "medial");
  InsideOracle oracle;
  BRepClass3d_SolidClassifier classifier(solid);
  if (withOracle)
    oracle = [&classifier](const Vec3& p) {
      classifier.Perform(gp_Pnt(p[0], p[1], p[2]), 1e-9);
      return classifier.State() == TopAbs_IN;
    };
  const SampleSet& samples = triangulated.sampled.samples;
  run.medial = computeCadMedial(*triangulated.triangulation, samples, *triangulated.prepared, params, oracle);
  run.secondsAxis = secondsSince(start);
  if (pairMesh) {
    call(stage, "pair_mesh");
    run.pairMesh = buildPairMeshStage(*triangulated.triangulation, samples, solid, run.medial);
    run.pairMesh->report["spacing"] = samples.spacing;
  }
  run.sampled = std::move(triangulated.sampled);
  return run;
}

bool pairMeshValid(const SolidResult& run) { return run.pairMesh->report.value("valid", false); }
std::size_t pairMeshInverted(const SolidResult& run) { return run.pairMesh->report.value("inverted", std::size_t{0}); }

}  // namespace

SolidResult runSolid(const TopoDS_Shape& solid, const SamplingParams& sampling, const MedialParams& params,
                  bool withOracle, bool pairMesh, const std::function<void(const char*)>& stage) {
  // A sampling again that fails (memory, OCCT) must not lose the result in
  // hand; a stop asked through `stage` (the Python module's cancel) must
  // still stop.
  bool stopped = false;
  const std::function<void(const char*)> reportStage = [&](const char* name) {
    if (!stage) return;
    try {
      stage(name);
    } catch (...) {
      stopped = true;
      throw;
    }
  };
  SolidResult best = attempt(solid, sampling, params, withOracle, pairMesh, reportStage);
  if (!pairMesh) return best;
  const double spacing = best.sampled.samples.spacing;  // the one asked, or the automatic one
  nlohmann::json attempts = nlohmann::json::array();
  // One entry per attempt: its result, or the error that ended the tries.
  auto record = [&attempts](double spacingTried, double factor, const SolidResult* run, const std::string& error) {
    nlohmann::json entry = {{"spacing", spacingTried}, {"spacing_factor", factor}};
    if (run) {
      entry["samples"] = run->sampled.samples.size();
      entry["inverted"] = pairMeshInverted(*run);
      entry["valid"] = pairMeshValid(*run);
    } else {
      entry["error"] = error.empty() ? std::string("unknown error") : error;
      entry["valid"] = false;
    }
    attempts.push_back(std::move(entry));
  };
  record(spacing, kPairMeshResampleFactors[0], &best, {});
  std::size_t kept = 0;
  for (std::size_t k = 1; k < std::size(kPairMeshResampleFactors) && !pairMeshValid(best); ++k) {
    SamplingParams finer = sampling;
    finer.spacing = kPairMeshResampleFactors[k] * spacing;
    SolidResult next;
    std::optional<std::string> error;
    try {
      next = attempt(solid, finer, params, withOracle, pairMesh, reportStage);
    } catch (const std::exception& e) {
      if (stopped) throw;
      error = e.what();
    } catch (const Standard_Failure& e) {
      if (stopped) throw;
      error = std::string("OpenCASCADE: ") + e.GetMessageString();
    } catch (...) {
      if (stopped) throw;
      error = "unknown error";
    }
    if (error) {
      record(finer.spacing, kPairMeshResampleFactors[k], nullptr, *error);
      break;
    }
    record(next.sampled.samples.spacing, kPairMeshResampleFactors[k], &next, {});
    // Valid beats not valid; among not valid ones, fewer inverted (the
    // first on a tie: the spacing asked).
    if (pairMeshValid(next) || pairMeshInverted(next) < pairMeshInverted(best)) {
      best = std::move(next);
      kept = k;
    }
  }
  for (std::size_t k = 0; k < attempts.size(); ++k) attempts[k]["kept"] = k == kept;
  best.pairMesh->report["attempts"] = std::move(attempts);
  return best;
}

}  // namespace cadmedial
