// summary.json of `cadmedial run`: counts, per-stage times and diagnostics.
#pragma once

#include <nlohmann/json.hpp>

#include "cadmedial/medial.hpp"
#include "cadmedial/sampling.hpp"

namespace cadmedial {

nlohmann::json medialSummaryJson(const SamplingReport& sampling, const MedialResult& medial, const MedialParams& params);

}  // namespace cadmedial
