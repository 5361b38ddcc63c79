// Bundled and public models for tests, and their expected properties.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace cadmedial::test {

// models/expected.json, one object per bundled model.
const std::vector<nlohmann::json>& bundledModels();
std::string bundledPath(const nlohmann::json& model);
// Names of the bundled models, for parameterised tests.
std::vector<std::string> bundledModelNames();
const nlohmann::json& bundledModel(const std::string& name);

// ../shared/models/public, or "" when the folder is missing (a user's clone).
std::string publicModelsDir();
// File names of MANIFEST.tsv rows whose notes contain `tag` (e.g. "set=dev").
std::vector<std::string> publicModels(const std::string& tag);

}  // namespace cadmedial::test
