#include "solid_run.hpp"

#include <chrono>
#include <cstdio>
#include <mutex>
#include <optional>
#include <string>

#include <tbb/enumerable_thread_specific.h>

#include <BRepClass3d_SolidClassifier.hxx>
#include <Standard_Failure.hxx>

#include "cadmedial/exact_oracle.hpp"

namespace cadmedial {

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void call(const std::function<void(const char*)>& stage, const char* name) {
  if (stage) stage(name);
}

// One sampling at `sampling` through the axis and, when asked, the pair-mesh.
// Stops after sampling (sameSamples) when the samples are `previous`: only
// the tolerances that scale with h (welding, near-surface tests) would
// differ, and the attempt is there to change the samples.
SolidResult attempt(const TopoDS_Shape& solid, const SamplingParams& sampling, const MedialParams& params,
                 bool withOracle, bool pairMesh, const std::function<void(const char*)>& stage,
                 const std::vector<Vec3>* previous = nullptr) {
  SolidResult run;
  call(stage, "sample");
  const auto start = Clock::now();
  // Local: the triangulation and the prepared samples are freed when this
  // attempt ends, so a sampling again does not hold two of them at once.
  TriangulatedSamples triangulated = sampleAndTriangulate(solid, sampling, params.mayReadCellSides());
  if (previous && triangulated.sampled.samples.points == *previous) {
    run.sameSamples = true;
    run.sampled = std::move(triangulated.sampled);
    return run;
  }
  call(stage, "medial");
  // One classifier: the relabel (exactSideNearSurface) calls it from one
  // thread; the check's fallback below takes a lock. A point OCCT fails on
  // counts as inside: the diagnostic then reports a disagreement, the
  // relabel keeps the facet (its rule before the exact side was asked).
  BRepClass3d_SolidClassifier classifier(solid);
  std::mutex classifierLock;
  auto stateOf = [&classifier](const Vec3& p, double tolerance) {
    try {
      classifier.Perform(gp_Pnt(p[0], p[1], p[2]), tolerance);
      return classifier.State();
    } catch (const Standard_Failure&) {
      return TopAbs_UNKNOWN;
    }
  };
  InsideOracle oracle;
  // The check asks ExactOracle (the evaluation's inside test: the normal at
  // a smooth nearest point, the convexity at a sharp edge, the classifier
  // only at vertices and where those are in doubt): OCCT's
  // classifier at every centroid cost 10-100 times the axis on curved
  // parts. The walk calls it from several threads: one copy per thread (the
  // copies share the meshes and boxes, medial_evaluation does the same).
  // Should the oracle's mesh fail, the classifier answers alone.
  std::optional<ExactOracle> exact;
  std::optional<tbb::enumerable_thread_specific<ExactOracle>> exactPerThread;
  if (withOracle) {
    try {
      exact.emplace(solid);
      exactPerThread.emplace(*exact);
    } catch (...) {
      exact.reset();
    }
    oracle = [&exact, &exactPerThread, &stateOf, &classifierLock](const Vec3& p) {
      if (!exact) {
        const std::lock_guard<std::mutex> hold(classifierLock);
        const TopAbs_State state = stateOf(p, 1e-9);
        return state == TopAbs_IN || state == TopAbs_UNKNOWN;
      }
      ExactOracle& local = exactPerThread->local();
      const gp_Pnt point(p[0], p[1], p[2]);
      // Most centroids are far from the surface: there the oracle's
      // closed mesh tells the side (ExactOracle::meshSide), in
      // microseconds; the exact test where it cannot or fails.
      try {
        if (const int side = local.meshSide(point, 2.0)) return side < 0;
      } catch (...) {
      }
      try {
        return local.inside(point, 1e-9);
      } catch (...) {
        return true;  // as a point the classifier fails on
      }
    };
  }
  const SampleSet& samples = triangulated.sampled.samples;
  // The pair-mesh labels ask the cell sides' question again with another
  // band: the link groups are kept for them (cell_sides.hpp).
  if (pairMesh && triangulated.prepared->cellSides) triangulated.prepared->cellSides->keepLinks = true;
  // Outside only when clearly so: a centroid on the surface (within 1e-3 h)
  // keeps its facet.
  const double onSurface = 1e-3 * samples.spacing;
  const InsideOracle notOutside = [&stateOf, onSurface](const Vec3& p) { return stateOf(p, onSurface) != TopAbs_OUT; };
  run.medial =
      computeCadMedial(*triangulated.triangulation, samples, *triangulated.prepared, params, oracle, notOutside);
  run.secondsAxis = secondsSince(start);
  if (pairMesh) {
    call(stage, "pair_mesh");
    run.pairMesh = buildPairMeshStage(*triangulated.triangulation, samples, solid, run.medial,
                                      triangulated.prepared->cellSides.get());
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
  // every_spacing: the curvature and wall-thickness bounds scaled too.
  auto record = [&attempts](double spacingTried, double factor, bool everySpacing, const SolidResult* run,
                            const std::string& error) {
    nlohmann::json entry = {{"spacing", spacingTried}, {"spacing_factor", factor}, {"every_spacing", everySpacing}};
    if (run) {
      entry["samples"] = run->sampled.samples.size();
      if (run->sameSamples) {
        entry["same_samples"] = true;  // as the attempt before: not run further
        entry["valid"] = false;
      } else {
        entry["inverted"] = pairMeshInverted(*run);
        entry["valid"] = pairMeshValid(*run);
      }
    } else {
      entry["error"] = error.empty() ? std::string("unknown error") : error;
      entry["valid"] = false;
    }
    attempts.push_back(std::move(entry));
  };
  record(spacing, 1.0, false, &best, {});
  std::size_t kept = 0;
  std::vector<Vec3> lastPoints;
  if (!pairMeshValid(best)) lastPoints = best.sampled.samples.points;
  for (std::size_t k = 0; k < std::size(kPairMeshResamples) && !pairMeshValid(best); ++k) {
    const PairMeshResample& retry = kPairMeshResamples[k];
    SamplingParams finer = sampling;
    finer.spacing = retry.factor * spacing;
    if (retry.boundsToo) finer.boundsScale = retry.factor * sampling.boundsScale;
    SolidResult next;
    std::optional<std::string> error;
    try {
      next = attempt(solid, finer, params, withOracle, pairMesh, reportStage, &lastPoints);
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
      record(finer.spacing, retry.factor, retry.boundsToo, nullptr, *error);
      break;
    }
    record(next.sampled.samples.spacing, retry.factor, retry.boundsToo, &next, {});
    if (next.sameSamples) continue;
    lastPoints = next.sampled.samples.points;
    // Valid beats not valid; among not valid ones, fewer inverted (the
    // first on a tie: the spacing asked).
    if (pairMeshValid(next) || pairMeshInverted(next) < pairMeshInverted(best)) {
      best = std::move(next);
      kept = k + 1;
    }
  }
  for (std::size_t k = 0; k < attempts.size(); ++k) attempts[k]["kept"] = k == kept;
  best.pairMesh->report["attempts"] = std::move(attempts);
  return best;
}

std::string resamplingLine(const nlohmann::json& attempts) {
  if (!attempts.is_array() || attempts.size() < 2) return {};
  auto spacing = [](const nlohmann::json& a) {
    char text[64];
    std::snprintf(text, sizeof text, "%.4g", a.value("spacing", 0.0));
    std::string s(text);
    if (a.value("every_spacing", false)) {
      std::snprintf(text, sizeof text, " with every spacing x %.2g", a.value("spacing_factor", 0.0));
      s += text;
    }
    return s;
  };
  auto verdict = [](const nlohmann::json& a) {
    if (a.contains("error")) return "failed: " + a["error"].get<std::string>();
    if (a.value("same_samples", false)) return std::string("the same samples, not run again");
    if (a.value("valid", false)) return std::string("valid");
    const auto inverted = a.value("inverted", std::size_t{0});
    return inverted > 0 ? std::to_string(inverted) + " inverted" : std::string("not valid");
  };
  std::string line = "not valid at spacing " + spacing(attempts[0]) + " (" + verdict(attempts[0]) + "), sampled again at";
  for (std::size_t k = 1; k < attempts.size(); ++k)
    line += std::string(k > 1 ? "," : "") + " " + spacing(attempts[k]) + " (" + verdict(attempts[k]) + ")";
  for (const auto& a : attempts)
    if (a.value("kept", false)) line += "; kept " + spacing(a);
  return line;
}

}  // namespace cadmedial
