// Bundled and public models for tests, and their expected properties.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

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

// The first of `warnings` that contains `text`, or "" when none does.
std::string warningContaining(const std::vector<std::string>& warnings, const std::string& text);

// A test with its own empty folder (dir_) under the system's temporary one,
// named after the suite and the process, removed after the test.
class ScratchDirTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
  std::filesystem::path dir_;
};

}  // namespace cadmedial::test
