#include "batch_results.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>

#include "cadmedial/errors.hpp"

namespace cadmedial {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json readJsonFile(const fs::path& path) {
  std::ifstream in(path);
  return json::parse(in, nullptr, /*allow_exceptions=*/false);  // discarded value if unreadable
}

// A value from eval.json, null when that field is absent (the eval schema may grow).
json pick(const json& j, const char* pointer) {
  const json::json_pointer p(pointer);
  return j.contains(p) ? j.at(p) : json(nullptr);
}

json evalHeadline(const json& e) {
  return {{"inside_share", pick(e, "/inside/share")},
          {"medialness_median", pick(e, "/medialness/median")},
          {"medialness_p90", pick(e, "/medialness/p90")},
          {"two_contact_share", pick(e, "/medialness/two_contact_share")},
          {"coverage_share", pick(e, "/coverage/share")},
          {"edge_attachment", pick(e, "/attachment/edge_share")},
          {"corner_attachment", pick(e, "/attachment/corner_share")},
          {"topology_matches", pick(e, "/topology/matches")},
          {"pass", pick(e, "/pass/all")}};
}

std::string utcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

std::string hostName() {
  char name[256] = {};
  ::gethostname(name, sizeof name - 1);
  return name;
}

const char* const kSolidFiles[] = {"medial.ply", "medial.obj", "medial.ma", "summary.json"};

}  // namespace

const char* statusName(FileStatus status) {
  switch (status) {
    case FileStatus::Ok: return "ok";
    case FileStatus::Error: return "error";
    case FileStatus::Timeout: return "timeout";
    case FileStatus::Crash: return "crash";
    case FileStatus::Oom: return "oom";
  }
  return "error";
}

nlohmann::ordered_json toJson(const FileResult& r) {
  static const std::string host = hostName();
  using ordered = nlohmann::ordered_json;
  return {{"path", r.path},
          {"output", r.output},
          {"status", statusName(r.status)},
          {"exit_code", r.exitCode >= 0 ? ordered(r.exitCode) : ordered(nullptr)},
          {"signal", r.signal > 0 ? ordered(r.signal) : ordered(nullptr)},
          {"step", r.step.empty() ? ordered(nullptr) : ordered(r.step)},
          {"message", r.message},
          {"wall_seconds", r.wallSeconds},
          {"peak_rss_mib", r.peakRssMiB},
          {"host", host},
          {"finished", utcNow()},
          {"solids", ordered(r.solids)}};
}

json readSolidSummaries(const std::string& folder) {
  json solids = json::array();
  for (int i = 0;; ++i) {
    const fs::path dir = fs::path(folder) / ("solid_" + std::to_string(i));
    const json summary = readJsonFile(dir / "summary.json");
    if (!summary.is_object()) break;
    json solid = {{"solid", i},
                  {"counts", summary.value("counts", json::object())},
                  {"topology", summary.value("topology", json::object())},
                  {"seconds", summary.value("seconds", json::object())}};
    const json eval = readJsonFile(dir / "eval.json");
    if (eval.is_object()) solid["eval"] = evalHeadline(eval);
    solids.push_back(std::move(solid));
  }
  return solids;
}

std::map<std::string, LastRecord> readLastRecords(const std::string& resultsPath) {
  std::map<std::string, LastRecord> last;
  std::ifstream in(resultsPath);
  std::string line;
  while (std::getline(in, line)) {
    const json r = json::parse(line, nullptr, false);
    if (!r.is_object() || !r.contains("output") || !r["output"].is_string()) continue;
    LastRecord record;
    record.path = r.value("path", "");
    record.status = r.value("status", "");
    const json solids = r.value("solids", json::array());
    for (const json& s : solids.is_array() ? solids : json::array()) {
      record.solids.push_back(s.is_object() ? s.value("solid", -1) : -1);
      record.solidHasEval.push_back(s.is_object() && s.contains("eval"));
    }
    last[r["output"].get<std::string>()] = std::move(record);
  }
  return last;
}

bool outputsComplete(const LastRecord& record, const std::string& folder) {
  if (record.status != "ok" || record.solids.empty()) return false;
  std::error_code ec;
  for (std::size_t i = 0; i < record.solids.size(); ++i) {
    const fs::path dir = fs::path(folder) / ("solid_" + std::to_string(record.solids[i]));
    for (const char* name : kSolidFiles)
      if (!fs::is_regular_file(dir / name, ec)) return false;
    if (record.solidHasEval[i] && !fs::is_regular_file(dir / "eval.json", ec)) return false;
  }
  return true;
}

ResultsLog::ResultsLog(const std::string& path) : path_(path) {
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) throw InputError(kExitOutputFailed, "cannot open " + path + ": " + std::strerror(errno));
  // A batch killed mid-write can leave a line without its newline; start on a
  // fresh line so the next record is not glued to the torn one.
  const off_t size = ::lseek(fd_, 0, SEEK_END);
  char lastChar = '\n';
  if (size > 0 && ::pread(fd_, &lastChar, 1, size - 1) == 1 && lastChar != '\n' && ::write(fd_, "\n", 1) != 1)
    throw InputError(kExitOutputFailed, "cannot write " + path + ": " + std::strerror(errno));
}

ResultsLog::~ResultsLog() {
  if (fd_ >= 0) ::close(fd_);
}

void ResultsLog::append(const nlohmann::ordered_json& record) {
  // Invalid UTF-8 in a child's message must not throw halfway through a batch.
  const std::string line = record.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
  if (::write(fd_, line.data(), line.size()) != ssize_t(line.size()) || ::fsync(fd_) != 0)
    throw InputError(kExitOutputFailed, "cannot append to " + path_ + ": " + std::strerror(errno));
}

}  // namespace cadmedial
