#include "batch_progress.hpp"

namespace cadmedial {

namespace {

constexpr FileStatus kStatuses[] = {FileStatus::Ok, FileStatus::Error, FileStatus::Timeout, FileStatus::Crash,
                                    FileStatus::Oom};
constexpr std::size_t kFailuresListed = 20;

std::string clock(double seconds) {
  const long s = long(seconds + 0.5);
  char text[32];
  if (s >= 3600)
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
  return text;
}

}  // namespace

BatchProgress::BatchProgress(std::FILE* out, bool redrawInPlace, std::size_t toRun, std::size_t skipped)
    : out_(out), redraw_(redrawInPlace), toRun_(toRun), skipped_(skipped), start_(std::chrono::steady_clock::now()) {
  if (skipped_ > 0) std::fprintf(out_, "resume: %zu file(s) already done, %zu to run\n", skipped_, toRun_);
}

double BatchProgress::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void BatchProgress::clearLine() {
  if (lineShown_) std::fputs("\r\033[K", out_);
  lineShown_ = false;
}

void BatchProgress::fileDone(const FileResult& r) {
  ++done_;
  ++counts_[int(r.status)];
  const bool failed = r.status != FileStatus::Ok;
  char head[96];
  std::snprintf(head, sizeof head, "[%zu/%zu] %-7s %7.1fs  ", done_, toRun_, statusName(r.status), r.wallSeconds);
  const std::string line = head + r.output + (failed ? ": " + r.message : "");
  if (failed) failureLines_.push_back(std::string(statusName(r.status)) + "  " + r.output + ": " + r.message);
  // On a terminal only failures scroll by; a log gets every file.
  if (redraw_ && !failed) return;
  clearLine();
  std::fprintf(out_, "%s\n", line.c_str());
  std::fflush(out_);
  lastDraw_ = {};
}

void BatchProgress::refresh(std::size_t running) {
  if (!redraw_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - lastDraw_ < std::chrono::milliseconds(500)) return;
  lastDraw_ = now;
  const double elapsed = elapsedSeconds();
  const double perMinute = elapsed > 0 ? 60.0 * double(done_) / elapsed : 0;
  const std::string eta = done_ > 0 ? clock(double(toRun_ - done_) * elapsed / double(done_)) : "?";
  clearLine();
  std::fprintf(out_, "[%zu/%zu] %zu failed | %.1f files/min | ETA %s | %zu running | %s elapsed", done_, toRun_,
               failures(), perMinute, eta.c_str(), running, clock(elapsed).c_str());
  std::fflush(out_);
  lineShown_ = true;
}

void BatchProgress::printSummary(const std::string& resultsPath, bool interrupted) {
  clearLine();
  const double elapsed = elapsedSeconds();
  std::fprintf(out_, "\nbatch %s: %zu of %zu file(s) in %s, %.1f files/min\n", interrupted ? "interrupted" : "done",
               done_, toRun_, clock(elapsed).c_str(), elapsed > 0 ? 60.0 * double(done_) / elapsed : 0.0);
  std::fprintf(out_, "  %-9s %8s\n", "status", "files");
  for (FileStatus s : kStatuses) std::fprintf(out_, "  %-9s %8zu\n", statusName(s), counts_[int(s)]);
  if (skipped_ > 0) std::fprintf(out_, "  %-9s %8zu  (ok in an earlier run, --resume)\n", "skipped", skipped_);
  if (interrupted) std::fprintf(out_, "  %-9s %8zu  (finish with --resume)\n", "not done", toRun_ - done_);
  if (!failureLines_.empty()) {
    std::fprintf(out_, "failures:\n");
    for (std::size_t i = 0; i < failureLines_.size() && i < kFailuresListed; ++i)
      std::fprintf(out_, "  %s\n", failureLines_[i].c_str());
    if (failureLines_.size() > kFailuresListed)
      std::fprintf(out_, "  ... and %zu more\n", failureLines_.size() - kFailuresListed);
  }
  std::fprintf(out_, "records: %s\n", resultsPath.c_str());
  std::fflush(out_);
}

}  // namespace cadmedial
