#include "batch_runner.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "batch_child.hpp"
#include "batch_inputs.hpp"
#include "batch_progress.hpp"
#include "batch_results.hpp"
#include "cadmedial/errors.hpp"

namespace cadmedial {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

// The children are this same executable; /proc/self/exe still works if the
// file on disk is replaced by a rebuild during a long batch.
constexpr const char* kSelf = "/proc/self/exe";

// ---- signals: handlers only set a flag and wake the main loop's poll() ----

volatile sig_atomic_t gStopSignal = 0;
int gWakeWrite = -1;

extern "C" void onSignal(int signal) {
  if (signal != SIGCHLD) gStopSignal = signal;
  const int saved = errno;
  [[maybe_unused]] const ssize_t ignored = ::write(gWakeWrite, "x", 1);
  errno = saved;
}

class SignalWakeup {
 public:
  SignalWakeup() {
    if (::pipe2(fds_, O_CLOEXEC | O_NONBLOCK) != 0)
      throw InputError(kExitProcessingFailed, std::string("pipe failed: ") + std::strerror(errno));
    gWakeWrite = fds_[1];
    gStopSignal = 0;
    struct sigaction action {};
    action.sa_handler = onSignal;
    action.sa_flags = SA_RESTART | SA_NOCLDSTOP;
    sigemptyset(&action.sa_mask);
    for (int i = 0; i < 3; ++i) ::sigaction(kSignals[i], &action, &previous_[i]);
  }
  ~SignalWakeup() {
    for (int i = 0; i < 3; ++i) ::sigaction(kSignals[i], &previous_[i], nullptr);
    gWakeWrite = -1;
    ::close(fds_[0]);
    ::close(fds_[1]);
  }
  // Sleeps until a signal arrives or `milliseconds` pass.
  void wait(int milliseconds) {
    pollfd p{fds_[0], POLLIN, 0};
    ::poll(&p, 1, milliseconds);
    char buffer[64];
    while (::read(fds_[0], buffer, sizeof buffer) > 0) {
    }
  }

 private:
  static constexpr int kSignals[3] = {SIGINT, SIGTERM, SIGCHLD};
  int fds_[2] = {-1, -1};
  struct sigaction previous_[3];
};

// ---- `cadmedial eval` may not exist in this build; ask the executable ----

struct EvalSupport {
  bool available = false;
  bool outputFlag = false;  // `eval MODEL -o DIR` rather than `eval MODEL DIR`
};

EvalSupport probeEval() {
  char path[4096];
  const ssize_t n = ::readlink(kSelf, path, sizeof path - 1);
  if (n <= 0) return {};
  path[n] = '\0';
  const std::string command = "'" + std::string(path) + "' eval --help 2>/dev/null";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return {};
  std::string help;
  char buffer[4096];
  while (std::size_t got = std::fread(buffer, 1, sizeof buffer, pipe)) help.append(buffer, got);
  const int status = ::pclose(pipe);
  EvalSupport support;
  // Without the subcommand, CLI11 may print the top-level help and exit 0.
  support.available = WIFEXITED(status) && WEXITSTATUS(status) == 0 && help.find("eval [OPTIONS]") != std::string::npos;
  support.outputFlag = help.find("--output") != std::string::npos;
  return support;
}

std::string readTail(const fs::path& path, std::size_t maxBytes = 64 * 1024) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size <= 0) return {};
  in.seekg(std::max<std::streamoff>(0, size - std::streamoff(maxBytes)));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Holds an exclusive lock on OUTDIR for the whole batch: two batches (or a
// batch and the Dask driver) writing one OUTDIR would do work twice and fight
// over the staging folder.
class OutputLock {
 public:
  explicit OutputLock(const fs::path& outDir) {
    const std::string path = (outDir / ".batch.lock").string();
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw InputError(kExitOutputFailed, "cannot create " + path + ": " + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0)
      throw InputError(kExitUsage, "another batch is writing to " + outDir.string() + " (lock " + path + ")");
  }
  ~OutputLock() { ::close(fd_); }

 private:
  int fd_ = -1;
};

struct Job {
  std::size_t input = 0;
  std::size_t step = 0;
  pid_t pid = -1;
  Clock::time_point start, deadline;
  bool timedOut = false;
  double peakRssMiB = 0;
};

class BatchRunner {
 public:
  BatchRunner(const BatchOptions& options, const EvalSupport& eval, std::vector<BatchInput> todo, ResultsLog& log,
              BatchProgress& progress)
      : options_(options), eval_(eval), todo_(std::move(todo)), log_(log), progress_(progress),
        outDir_(options.outDir), stageRoot_(outDir_ / ".batch-tmp") {}

  // Returns the signal that stopped the batch, 0 if every file was attempted.
  int run() {
    SignalWakeup wakeup;
    const std::size_t jobs = options_.jobs > 0 ? options_.jobs : std::max(1u, std::thread::hardware_concurrency());
    std::size_t next = 0;
    while (gStopSignal == 0) {
      while (running_.size() < jobs && next < todo_.size() && gStopSignal == 0) launch(next++);
      if (running_.empty()) break;
      wakeup.wait(millisecondsToNextEvent());
      reapFinished();
      killOverdue();
      progress_.refresh(running_.size());
    }
    if (gStopSignal != 0) abandonRunning();
    return gStopSignal;
  }

 private:
  fs::path stageOf(const Job& job) const { return stageRoot_ / std::to_string(job.input); }
  fs::path stagedOutputs(const Job& job) const { return stageOf(job) / "out"; }
  std::size_t stepCount() const { return options_.eval ? 2 : 1; }
  const char* stepName(std::size_t step) const { return step == 0 ? "run" : "eval"; }

  std::vector<std::string> stepArguments(const Job& job) const {
    const BatchInput& in = todo_[job.input];
    const std::string out = stagedOutputs(job).string();
    if (job.step == 0) {
      std::vector<std::string> args{"run", in.path, "-o", out};
      args.insert(args.end(), options_.runArguments.begin(), options_.runArguments.end());
      return args;
    }
    if (eval_.outputFlag) return {"eval", in.path, "-o", out};
    return {"eval", in.path, out};
  }

  fs::path stderrOf(const Job& job) const { return stageOf(job) / (std::string(stepName(job.step)) + ".stderr"); }

  void launch(std::size_t input) {
    Job job;
    job.input = input;
    job.start = Clock::now();
    job.deadline = job.start + std::chrono::duration_cast<Clock::duration>(
                                   std::chrono::duration<double>(options_.timeoutSeconds));
    // A staging folder that cannot be made (disk full, a file in the way)
    // fails this file with the output exit code; the batch goes on.
    std::error_code ec;
    fs::create_directories(stageOf(job), ec);
    if (ec) return recordUnstarted(job, "cannot create " + stageOf(job).string() + ": " + ec.message());
    startStep(job);
  }

  // Outputs exist only when the file's last record is ok (publishOrDiscard):
  // an earlier run's go, as for any failure.
  void recordUnstarted(const Job& job, const std::string& message) {
    FileResult r;
    r.path = todo_[job.input].path;
    r.output = todo_[job.input].output;
    std::error_code ignored;
    fs::remove_all(outDir_ / r.output, ignored);
    failPublish(r, message);
    r.step = "stage";
    log_.append(toJson(r));
    progress_.fileDone(r);
  }

  void startStep(Job job) {
    job.pid = startChild(kSelf, stepArguments(job), stderrOf(job).string(), options_.maxMemoryGiB);
    running_.push_back(job);
  }

  int millisecondsToNextEvent() const {
    int ms = 500;  // progress redraw
    if (options_.timeoutSeconds <= 0) return ms;
    const auto now = Clock::now();
    for (const Job& job : running_) {
      if (job.timedOut) continue;
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(job.deadline - now).count();
      ms = int(std::clamp<long long>(left + 1, 1, ms));
    }
    return ms;
  }

  void killOverdue() {
    if (options_.timeoutSeconds <= 0) return;
    const auto now = Clock::now();
    for (Job& job : running_)
      if (!job.timedOut && now >= job.deadline) {
        ::kill(-job.pid, SIGKILL);  // the whole group: whatever the step started dies too
        job.timedOut = true;
      }
  }

  void reapFinished() {
    int status = 0;
    rusage usage{};
    pid_t pid;
    while ((pid = ::wait4(-1, &status, WNOHANG, &usage)) > 0) {
      auto it = std::find_if(running_.begin(), running_.end(), [pid](const Job& j) { return j.pid == pid; });
      if (it == running_.end()) continue;
      Job job = *it;
      running_.erase(it);
      const ChildExit exit = decodeChildExit(status, usage.ru_maxrss);
      job.peakRssMiB = std::max(job.peakRssMiB, exit.peakRssMiB);
      if (exit.exitCode == 0 && !job.timedOut && job.step + 1 < stepCount()) {
        ++job.step;
        startStep(job);
      } else {
        finish(job, exit);
      }
    }
  }

  void finish(const Job& job, const ChildExit& exit) {
    const BatchInput& in = todo_[job.input];
    const std::string stderrText = readTail(stderrOf(job));
    FileResult r;
    r.path = in.path;
    r.output = in.output;
    r.status = classifyChild(exit, job.timedOut, stderrText);
    r.exitCode = job.timedOut ? -1 : exit.exitCode;
    r.signal = job.timedOut ? 0 : exit.signal;
    r.peakRssMiB = job.peakRssMiB;
    if (r.status != FileStatus::Ok) {
      r.step = stepName(job.step);
      r.message = describeFailure(r.status, exit, options_.timeoutSeconds, stderrText);
    } else {
      r.solids = readSolidSummaries(stagedOutputs(job).string());
      if (r.solids.empty()) {
        r.status = FileStatus::Error;
        r.step = "run";
        r.message = "exited 0 but wrote no solid_<i>/summary.json";
      }
    }
    r.wallSeconds = std::chrono::duration<double>(Clock::now() - job.start).count();
    publishOrDiscard(job, r);
    // Nothing but the append between the rename and the record: a SIGKILL of
    // the batch there leaves one complete, unrecorded folder, which --resume redoes.
    log_.append(toJson(r));
    progress_.fileDone(r);
    std::error_code ignored;
    fs::remove_all(stageOf(job), ignored);
  }

  // Outputs under OUTDIR/<output>/ exist exactly when the file's last record
  // is ok: complete new outputs replace old ones by rename, and a failure
  // removes outputs of an earlier run rather than leave them to look current.
  // The one exception is a batch killed by SIGKILL between this rename and
  // the record's append (see finish); --resume redoes that file.
  void publishOrDiscard(const Job& job, FileResult& r) {
    const fs::path target = outDir_ / r.output;
    std::error_code ec;
    // Only folders are outputs: `batch results.jsonl -o .` must not take the log away.
    std::error_code missing;  // ENOENT is the usual case, not an error
    const fs::file_status existing = fs::symlink_status(target, missing);
    if (fs::exists(existing) && !fs::is_directory(existing)) {
      if (r.status == FileStatus::Ok) failPublish(r, target.string() + " exists and is not an output folder");
      return;
    }
    if (fs::exists(existing)) fs::rename(target, stageOf(job) / "previous", ec);
    if (ec) return failPublish(r, "cannot move old outputs " + target.string() + " aside: " + ec.message());
    if (r.status != FileStatus::Ok) return;
    fs::create_directories(target.parent_path(), ec);
    if (!ec) fs::rename(stagedOutputs(job), target, ec);
    if (ec) failPublish(r, "cannot move outputs to " + target.string() + ": " + ec.message());
  }

  static void failPublish(FileResult& r, const std::string& message) {
    r.status = FileStatus::Error;
    r.exitCode = kExitOutputFailed;
    r.step = "publish";
    r.message = message;
    r.solids = nlohmann::json::array();
  }

  // Ctrl-C: nothing half-done is recorded; --resume redoes these files.
  void abandonRunning() {
    for (const Job& job : running_) ::kill(-job.pid, SIGKILL);
    for (const Job& job : running_) {
      int status = 0;
      while (::waitpid(job.pid, &status, 0) < 0 && errno == EINTR) {
      }
    }
    running_.clear();
  }

  const BatchOptions& options_;
  EvalSupport eval_;
  std::vector<BatchInput> todo_;
  ResultsLog& log_;
  BatchProgress& progress_;
  fs::path outDir_, stageRoot_;
  std::vector<Job> running_;
};

}  // namespace

int runBatchCommand(const BatchOptions& options) {
  const fs::path outDir = fs::absolute(options.outDir);
  const EvalSupport eval = options.eval ? probeEval() : EvalSupport{};
  if (options.eval && !eval.available)
    throw InputError(kExitUsage, "--eval needs the `cadmedial eval` subcommand, which this build does not have");
  std::vector<BatchInput> inputs = collectBatchInputs(options.inputs, outDir.string());

  std::error_code ec;
  fs::create_directories(outDir, ec);
  if (ec) throw InputError(kExitOutputFailed, "cannot create " + outDir.string() + ": " + ec.message());
  OutputLock lock(outDir);
  // Left over by a batch that was killed; nothing in it was ever published.
  fs::remove_all(outDir / ".batch-tmp", ec);

  const std::string resultsPath = (outDir / "results.jsonl").string();
  const std::size_t total = inputs.size();
  std::vector<BatchInput> todo;
  if (options.resume) {
    const auto last = readLastRecords(resultsPath);
    for (BatchInput& in : inputs) {
      const auto it = last.find(in.output);
      const bool done = it != last.end() && it->second.path == in.path &&
                        outputsComplete(it->second, (outDir / in.output).string());
      if (!done) todo.push_back(std::move(in));
    }
  } else {
    todo = std::move(inputs);
  }
  const std::size_t skipped = total - todo.size();

  ResultsLog log(resultsPath);
  BatchProgress progress(stderr, ::isatty(STDERR_FILENO) == 1, todo.size(), skipped);
  BatchRunner runner(options, eval, std::move(todo), log, progress);
  const int stopSignal = runner.run();
  fs::remove_all(outDir / ".batch-tmp", ec);
  progress.printSummary(resultsPath, stopSignal != 0);
  if (stopSignal != 0) return 128 + stopSignal;
  return progress.failures() > 0 ? kExitProcessingFailed : kExitOk;
}

}  // namespace cadmedial
