#include "batch_inputs.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <set>
#include <system_error>

#include "cadmedial/errors.hpp"

namespace cadmedial {

namespace fs = std::filesystem;

namespace {

std::string lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

bool isManifestName(const std::string& name) {
  const std::string ext = lowercase(fs::path(name).extension().string());
  return ext == ".txt" || ext == ".lst";
}

// Output folder of `path` relative to `base`; outside the base, the absolute
// path without its root, so distinct files never share a folder by accident.
std::string outputFolder(const fs::path& path, const fs::path& base) {
  const fs::path rel = path.lexically_relative(base);
  if (rel.empty() || *rel.begin() == "..") return path.relative_path().generic_string();
  return rel.generic_string();
}

class InputCollector {
 public:
  explicit InputCollector(const std::string& skipFolder) {
    std::error_code ec;
    if (!skipFolder.empty() && fs::exists(skipFolder, ec)) skip_ = fs::canonical(skipFolder, ec);
  }

  void addArgument(const std::string& argument) {
    if (argument.size() > 1 && argument[0] == '@') return addManifest(argument.substr(1));
    std::error_code ec;
    if (fs::is_directory(argument, ec)) return addFolder(absolute(argument));
    if (isManifestName(argument)) return addManifest(argument);
    addFile(absolute(argument), fs::current_path());
  }

  // Drops repeats of a file (the first one stays) and rejects two files with
  // one output folder. Sorting indices rather than keeping sets of names: no
  // second copy of a million paths.
  std::vector<BatchInput> take() {
    if (inputs_.empty()) throw InputError(kExitUsage, "no input files found (looked for .step .stp .iges .igs .brep)");
    std::vector<std::size_t> order(inputs_.size());
    std::iota(order.begin(), order.end(), 0);
    std::vector<bool> repeated(inputs_.size(), false);
    const auto byField = [&](std::string BatchInput::*field) {
      std::stable_sort(order.begin(), order.end(),
                       [&](std::size_t a, std::size_t b) { return inputs_[a].*field < inputs_[b].*field; });
    };
    byField(&BatchInput::path);
    for (std::size_t k = 1; k < order.size(); ++k)
      if (inputs_[order[k]].path == inputs_[order[k - 1]].path) repeated[order[k]] = true;
    order.erase(std::remove_if(order.begin(), order.end(), [&](std::size_t i) { return repeated[i]; }), order.end());
    byField(&BatchInput::output);
    for (std::size_t k = 1; k < order.size(); ++k) {
      const BatchInput &a = inputs_[order[k - 1]], &b = inputs_[order[k]];
      if (a.output == b.output)
        throw InputError(kExitUsage, "two inputs would share the output folder '" + a.output + "': " + a.path +
                                         " and " + b.path + " (list them from a common folder or manifest)");
    }
    std::vector<BatchInput> unique;
    unique.reserve(order.size());
    for (std::size_t i = 0; i < inputs_.size(); ++i)
      if (!repeated[i]) unique.push_back(std::move(inputs_[i]));
    return unique;
  }

 private:
  static fs::path absolute(const fs::path& p) { return fs::absolute(p).lexically_normal(); }

  void addFile(const fs::path& path, const fs::path& base) {
    inputs_.push_back({path.string(), outputFolder(path, base)});
  }

  void addFolder(const fs::path& folder) {
    std::vector<fs::path> files;
    std::error_code ec;
    fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec), end;
    if (ec) throw InputError(kExitUsage, "cannot list " + folder.string() + ": " + ec.message());
    for (; it != end; it.increment(ec)) {
      if (ec) throw InputError(kExitUsage, "cannot list " + folder.string() + ": " + ec.message());
      const std::string name = it->path().filename().string();
      std::error_code ignored;
      // Hidden entries (.git, our own .batch-tmp) and the output folder itself
      // (`batch . -o out`) are never inputs.
      const bool hidden = name.empty() || name[0] == '.';
      if (it->is_directory(ignored)) {
        if (hidden || (!skip_.empty() && fs::equivalent(it->path(), skip_, ignored))) it.disable_recursion_pending();
      } else if (!hidden && isCadFileName(name) && it->is_regular_file(ignored)) {
        files.push_back(it->path().lexically_normal());
      }
    }
    std::sort(files.begin(), files.end());  // directory order is arbitrary; runs should not be
    for (const fs::path& f : files) addFile(f, folder);
  }

  void addManifest(const std::string& manifest) {
    std::ifstream in(manifest);
    if (!in) throw InputError(kExitUsage, "cannot read manifest " + manifest);
    const fs::path base = absolute(manifest).parent_path();
    std::string line;
    while (std::getline(in, line)) {
      const auto first = line.find_first_not_of(" \t\r");
      if (first == std::string::npos || line[first] == '#') continue;
      const auto last = line.find_last_not_of(" \t\r");
      // base / "/abs/path" is "/abs/path": absolute entries stay as they are.
      const fs::path entry = absolute(base / line.substr(first, last - first + 1));
      std::error_code ec;
      if (fs::is_directory(entry, ec))
        addFolder(entry);
      else
        addFile(entry, base);
    }
  }

  fs::path skip_;
  std::vector<BatchInput> inputs_;
};

}  // namespace

bool isCadFileName(const std::string& name) {
  static const std::set<std::string> extensions{".step", ".stp", ".iges", ".igs", ".brep"};
  return extensions.count(lowercase(fs::path(name).extension().string())) > 0;
}

std::vector<BatchInput> collectBatchInputs(const std::vector<std::string>& arguments, const std::string& skipFolder) {
  InputCollector collector(skipFolder);
  for (const std::string& a : arguments) collector.addArgument(a);
  return collector.take();
}

}  // namespace cadmedial
