// JSON forms of the reports, for summary files and the Python module.
#pragma once

#include <nlohmann/json.hpp>

#include "cadmedial/sampling.hpp"

namespace cadmedial {

nlohmann::json toJson(const FeatureCounts& c);
nlohmann::json toJson(const SurfaceMeshStats& s);
nlohmann::json toJson(const SamplingReport& r);

}  // namespace cadmedial
