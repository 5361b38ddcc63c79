// What a batch tells the person watching it: on a terminal one progress line
// redrawn in place (failures printed above it), in a log one plain line per
// file; a summary table at the end.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "batch_results.hpp"

namespace cadmedial {

class BatchProgress {
 public:
  // `toRun` files will be attempted; `skipped` were already done (--resume).
  BatchProgress(std::FILE* out, bool redrawInPlace, std::size_t toRun, std::size_t skipped);

  void fileDone(const FileResult& result);
  void refresh(std::size_t running);  // cheap to call often: redraws at most twice a second
  void printSummary(const std::string& resultsPath, bool interrupted);

  std::size_t failures() const { return done_ - counts_[0]; }

 private:
  double elapsedSeconds() const;
  void clearLine();

  std::FILE* out_;
  bool redraw_;
  std::size_t toRun_, skipped_, done_ = 0;
  std::size_t counts_[5] = {};  // by FileStatus
  std::vector<std::string> failureLines_;
  std::chrono::steady_clock::time_point start_, lastDraw_;
  bool lineShown_ = false;
};

}  // namespace cadmedial
