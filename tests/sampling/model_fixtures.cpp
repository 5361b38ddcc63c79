#include "model_fixtures.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace cadmedial::test {

const std::vector<nlohmann::json>& bundledModels() {
  static const std::vector<nlohmann::json> models = [] {
    std::ifstream in(std::string(CADMEDIAL_MODELS_DIR) + "/expected.json");
    if (!in) throw std::runtime_error("models/expected.json missing");
    const nlohmann::json doc = nlohmann::json::parse(in);
    return doc.at("models").get<std::vector<nlohmann::json>>();
  }();
  return models;
}

std::string bundledPath(const nlohmann::json& model) {
  return std::string(CADMEDIAL_MODELS_DIR) + "/" + model.at("file").get<std::string>();
}

std::vector<std::string> bundledModelNames() {
  std::vector<std::string> names;
  for (const auto& m : bundledModels()) names.push_back(m.at("name").get<std::string>());
  return names;
}

const nlohmann::json& bundledModel(const std::string& name) {
  for (const auto& m : bundledModels())
    if (m.at("name") == name) return m;
  throw std::runtime_error("no bundled model " + name);
}

std::string publicModelsDir() {
  const std::string dir = CADMEDIAL_PUBLIC_MODELS_DIR;
  return std::filesystem::exists(dir + "/MANIFEST.tsv") ? dir : "";
}

std::vector<std::string> publicModels(const std::string& tag) {
  std::vector<std::string> files;
  const std::string dir = publicModelsDir();
  if (dir.empty()) return files;
  std::ifstream in(dir + "/MANIFEST.tsv");
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string file;
    std::getline(row, file, '\t');
    if (line.find(tag) != std::string::npos) files.push_back(file);
  }
  return files;
}

void ScratchDirTest::SetUp() {
  const std::string suite = ::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name();
  dir_ = std::filesystem::temp_directory_path() / ("cadmedial_" + suite + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir_);
}

void ScratchDirTest::TearDown() { std::filesystem::remove_all(dir_); }

std::string warningContaining(const std::vector<std::string>& warnings, const std::string& text) {
  for (const std::string& w : warnings)
    if (w.find(text) != std::string::npos) return w;
  return "";
}

}  // namespace cadmedial::test
