// `cadmedial batch`: `cadmedial run` (and `eval`) over many files, each file in
// its own child process, so that one bad file never costs the others.
#pragma once

#include <string>
#include <vector>

namespace cadmedial {

struct BatchOptions {
  std::vector<std::string> inputs;        // files, folders, manifests (see batch_inputs.hpp)
  std::string outDir;
  unsigned jobs = 0;                      // files at once; 0: number of cores
  double timeoutSeconds = 0;              // per file, all steps together; 0: none
  double maxMemoryGiB = 0;                // address-space limit per process; 0: none
  bool resume = false;                    // skip files whose last record is ok and whose outputs exist
  bool eval = false;                      // run `cadmedial eval` after `run`
  std::vector<std::string> runArguments;  // passed on to every `cadmedial run` (--spacing H ...)
};

// Exit codes: 0 every file ok (or skipped), 1 some file failed, 2 bad command
// line or inputs, 5 OUTDIR or results.jsonl not writable, 128+signal when
// stopped by SIGINT (130) or SIGTERM (143). Throws InputError for 2 and 5.
int runBatchCommand(const BatchOptions& options);

}  // namespace cadmedial
