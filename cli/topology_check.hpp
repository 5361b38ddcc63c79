// The axis's Betti numbers against the solid's, after a run: they differ
// where a feature is finer than the sampling resolves (a small hole, a thin
// wall, a nearly flat convex edge), and the user should know.
#pragma once

#include <string>

#include "cadmedial/medial.hpp"
#include "cadmedial/medial_evaluation.hpp"

namespace cadmedial {

// One line for a warning, empty when β0 and β1 match (or β1 of either is
// unknown and β0 matches). `spacing` is the h used: the line suggests h / 2.
std::string topologyMismatchWarning(const ComplexTopology& axis, const SolidBetti& solid, double spacing);

}  // namespace cadmedial
