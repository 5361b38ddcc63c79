// One solid through sampling, CAD_MEDIAL and, when asked, the pair-mesh: the
// shared part of `cadmedial run` and the Python module's compute().
//
// Why the pair-mesh can resample: whether its repair leaves an element
// inverted depends on the exact samples, not only on the shape (the lever
// and NIST CTC-01 are valid at most spacings and not at a few in between;
// ARCHITECTURE.md, "Known gaps"). A CAD engineer asked for a valid mesh at
// about spacing h, so when the first pair-mesh is not valid the solid is
// sampled again a little finer (h × 0.97, then every spacing × 0.94: h and
// the curvature and wall-thickness bounds, kPairMeshResamples) and the first valid
// result is kept, axis and pair-mesh together (they share the samples); if
// none is, the one with the fewest inverted elements. Every attempt is
// reported ("attempts" in the pair-mesh report; a sampling again that throws
// is recorded with its "error" and ends the tries, keeping what was in hand)
// and `spacing` in the summary is the one kept.
#pragma once

// CGAL (core) headers before OCCT's.
#include "cadmedial/medial.hpp"

#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include <TopoDS_Shape.hxx>

#include "cadmedial/sample_and_triangulate.hpp"
#include "pair_mesh_stage.hpp"

namespace cadmedial {

struct SolidResult {
  SolidSampling sampled;                  // the samples kept (their triangulation is freed per attempt)
  MedialResult medial;
  std::optional<PairMeshStage> pairMesh;  // when asked; its report has "attempts" and "spacing" (the kept one)
  double secondsAxis = 0;                 // wall time from sampling to the axis, of the attempt kept
  bool sameSamples = false;               // an attempt stopped after sampling: the samples of the one before
};

// The attempts after the first (the spacing asked), tried only while the
// pair-mesh is not valid: h × factor, and with `boundsToo` the curvature and
// wall-thickness bounds too (SamplingParams::boundsScale). Measured
// 2026-12-02: h alone at 0.97 makes the lever, NIST CTC-01 and a star prism
// valid, where every spacing × 0.97 and × 0.94 left CTC-01 with 1-2
// inverted; a torus of minor radius 2, all of whose spacing the curvature
// sets, gets the same samples from h alone and is valid with every spacing
// × 0.94. (Another random seed at h left the lever and CTC-01 not valid.)
struct PairMeshResample {
  double factor;
  bool boundsToo;
};
constexpr PairMeshResample kPairMeshResamples[] = {{0.97, false}, {0.94, true}};

// stage(name) is called before "sample", "medial" and "pair_mesh" of every
// attempt (it may throw to stop). withOracle: count walk-vs-exact-classifier
// disagreements (MedialResult::counts).
SolidResult runSolid(const TopoDS_Shape& solid, const SamplingParams& sampling, const MedialParams& params,
                  bool withOracle, bool pairMesh, const std::function<void(const char* stage)>& stage = {});

// The attempts of a pair-mesh report ("attempts", above) as one line, e.g.
// "not valid at spacing 8.93 (1 inverted), sampled again at 8.662 (valid);
// kept 8.662"; empty when the solid was sampled once. The CLI and the
// workbench's Report view both print it.
std::string resamplingLine(const nlohmann::json& attempts);

}  // namespace cadmedial
