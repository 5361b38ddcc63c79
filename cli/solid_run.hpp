// One solid through sampling, CAD_MEDIAL and, when asked, the pair-mesh: the
// shared part of `cadmedial run` and the Python module's compute().
//
// Why the pair-mesh can resample: whether its repair leaves an element
// inverted depends on the exact samples, not only on the shape (the lever
// and NIST CTC-01 are valid at most spacings and not at a few in between;
// ARCHITECTURE.md, "Known gaps"). A CAD engineer asked for a valid mesh at
// about spacing h, so when the first pair-mesh is not valid the solid is
// sampled again a little finer (h × 0.97, then h × 0.94) and the first valid
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

#include <TopoDS_Shape.hxx>

#include "cadmedial/sample_and_triangulate.hpp"
#include "pair_mesh_stage.hpp"

namespace cadmedial {

struct SolidResult {
  SolidSampling sampled;                  // the samples kept (their triangulation is freed per attempt)
  MedialResult medial;
  std::optional<PairMeshStage> pairMesh;  // when asked; its report has "attempts" and "spacing" (the kept one)
  double secondsAxis = 0;                 // wall time from sampling to the axis, of the attempt kept
};

// Spacing factors of the attempts: 1 (the spacing asked), then finer ones,
// tried only while the pair-mesh is not valid.
constexpr double kPairMeshResampleFactors[] = {1.0, 0.97, 0.94};

// stage(name) is called before "sample", "medial" and "pair_mesh" of every
// attempt (it may throw to stop). withOracle: count walk-vs-exact-classifier
// disagreements (MedialResult::counts).
SolidResult runSolid(const TopoDS_Shape& solid, const SamplingParams& sampling, const MedialParams& params,
                  bool withOracle, bool pairMesh, const std::function<void(const char* stage)>& stage = {});

}  // namespace cadmedial
