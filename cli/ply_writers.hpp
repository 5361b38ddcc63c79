// PLY files of the samples and of the stitched boundary mesh, readable by
// MeshLab and ParaView.
#pragma once

#include <ostream>

#include "cadmedial/sample_set.hpp"

namespace cadmedial {

// Points with per-vertex properties: kind (0 face, 1 edge, 2 vertex), owner,
// convex (on a convex edge), nonconcave (non-concave corner), triplet_role
// (0 none, 1 edge sample s, 2 leg), and red/green/blue by kind for viewers.
// The triplet legs are written as PLY edges (s-sLeft, s-sRight).
void writeSamplesPly(std::ostream& out, const SampleSet& samples);

// The stitched boundary mesh with the owning face id per triangle.
void writeBoundaryMeshPly(std::ostream& out, const SampleSet& samples);

}  // namespace cadmedial
