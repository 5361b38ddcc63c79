// sampleSolid with the Delaunay triangulation of its points built on a
// thread of its own meanwhile, and the samples' part of CAD_MEDIAL prepared
// while it runs: on two cores the face reconstruction and that preparation
// then cost no wall time (10^6-sample box: ~7 s of 34).
#pragma once

// CGAL (core) headers before OCCT's: OCCT defines a `Handle` macro.
#include "cadmedial/medial.hpp"

#include <memory>

#include "cadmedial/sampling.hpp"

namespace cadmedial {

struct TriangulatedSamples {
  SolidSampling sampled;
  std::unique_ptr<DelaunayVoronoi> triangulation;  // of sampled.samples.points
  std::unique_ptr<PreparedSamples> prepared;       // for computeCadMedial(dv, samples, *prepared, params)
};

// prepareCellSides: also build the cell-side inputs (MedialParams::mayReadCellSides()).
// If no thread can be started (a memory limit), the triangulation is built
// afterwards on the calling thread. Throws what sampleSolid, the
// triangulation or the preparation throw.
TriangulatedSamples sampleAndTriangulate(const TopoDS_Shape& solid, const SamplingParams& params,
                                         bool prepareCellSides);

}  // namespace cadmedial
