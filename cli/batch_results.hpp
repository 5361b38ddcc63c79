// One record per finished file in OUTDIR/results.jsonl (schema in the README):
// the log users grep, the progress and summary read, and --resume trusts.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace cadmedial {

enum class FileStatus { Ok, Error, Timeout, Crash, Oom };
const char* statusName(FileStatus status);

struct FileResult {
  std::string path;
  std::string output;       // folder under OUTDIR
  FileStatus status = FileStatus::Error;
  int exitCode = -1;        // -1 when the process did not exit by itself
  int signal = 0;           // the signal that ended it, 0 if none
  std::string step;         // what failed ("run", "eval", "stage", "publish"); empty when ok
  std::string message;      // one line: the child's error, or what the batch saw
  double wallSeconds = 0;
  double peakRssMiB = 0;    // largest resident set of the file's processes
  nlohmann::json solids = nlohmann::json::array();  // per solid: counts, topology, seconds, eval
};

// Field order as in the README, so records read well in a terminal.
nlohmann::ordered_json toJson(const FileResult& result);

// Per solid of a finished `run` (and `eval`) in `folder`: counts, topology and
// stage seconds from summary.json, the headline metrics of eval.json.
nlohmann::json readSolidSummaries(const std::string& folder);

// What --resume needs of a file's last record; only this is kept in memory,
// since a results.jsonl of a million files holds gigabytes of parsed JSON.
struct LastRecord {
  std::string path;
  std::string status;
  std::vector<int> solids;         // the solid_<i> folders the record vouches for
  std::vector<bool> solidHasEval;  // ... and which of them have eval.json
};

// Last parsable record per output folder. A torn last line (batch killed while
// writing) is skipped, not fatal.
std::map<std::string, LastRecord> readLastRecords(const std::string& resultsPath);

// True if `record` is ok and every file it vouches for exists under `folder`.
bool outputsComplete(const LastRecord& record, const std::string& folder);

// Appends records to results.jsonl, each with one write() and an fsync, so a
// record on disk is complete and survives a crash of the machine.
class ResultsLog {
 public:
  explicit ResultsLog(const std::string& path);  // throws InputError(kExitOutputFailed)
  ~ResultsLog();
  ResultsLog(const ResultsLog&) = delete;
  ResultsLog& operator=(const ResultsLog&) = delete;
  void append(const nlohmann::ordered_json& record);  // throws InputError(kExitOutputFailed)

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace cadmedial
