// The axis's Betti numbers against the solid's, after a run: they differ
// where a feature is finer than the sampling resolves (a small hole, a thin
// wall, a nearly flat convex edge), and the user should know.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "cadmedial/medial.hpp"
// OCCT after CGAL (OCCT's Handle macro).
#include <TopoDS_Shape.hxx>

#include "cadmedial/medial_evaluation.hpp"

namespace cadmedial {

// One line for a warning, empty when β0, β1 and β2 match (or β1 of either
// is unknown and β0 matches). `spacing` is the h used: the line suggests h / 2
// (--spacing in the CLI, spacing= in Python).
std::string topologyMismatchWarning(const ComplexTopology& axis, const SolidBetti& solid, double spacing);

// The solid's Betti numbers into summary["topology"]["solid"] and the
// warning (or "") into summary["topology"]["warning"]; returns the warning.
// For `cadmedial run` and the Python module alike.
std::string recordSolidTopology(nlohmann::json& summary, const TopoDS_Shape& solid, const ComplexTopology& axis,
                                double spacing);

}  // namespace cadmedial
