// summary.json of `cadmedial run`: counts, per-stage times and diagnostics.
#pragma once

#include <nlohmann/json.hpp>

#include "cadmedial/compute_medial.hpp"
#include "cadmedial/medial.hpp"
#include "cadmedial/sampling.hpp"
#include "point_input.hpp"

namespace cadmedial {

nlohmann::json medialSummaryJson(const SamplingReport& sampling, const MedialResult& medial, const MedialParams& params);

// The same for MEDIAL on a point cloud or mesh ("algorithm": "MEDIAL", "axis": "whole" | "inner").
nlohmann::json pointMedialSummaryJson(const PointInput& input, const PointMedialResult& medial, const MedialParams& params);

}  // namespace cadmedial
