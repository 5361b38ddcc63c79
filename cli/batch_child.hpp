// One step of one file's job (`cadmedial run` or `eval`) as a child process.
// Each child leads its own process group, so the batch can kill everything it
// started at once, and a terminal's Ctrl-C reaches only the batch, which then
// decides what to kill and what to record.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

#include "batch_results.hpp"

namespace cadmedial {

// Starts `executable` with `arguments` (argv[1..]) in a new process group with
// stdin/stdout on /dev/null and stderr into `stderrPath`; the child dies with
// the batch (PR_SET_PDEATHSIG) and gets an address-space limit when
// maxMemoryGiB > 0. Throws InputError(kExitProcessingFailed) if fork fails.
pid_t startChild(const std::string& executable, const std::vector<std::string>& arguments,
                 const std::string& stderrPath, double maxMemoryGiB);

// How a child ended, decoded from wait4().
struct ChildExit {
  int exitCode = -1;  // -1 if killed by a signal
  int signal = 0;
  double peakRssMiB = 0;
};
ChildExit decodeChildExit(int waitStatus, long maxRssKiB);

// The line to show for a failed child: its last "error: ..." line (prefix
// removed), else its last non-empty line; at most 500 characters.
std::string errorLineOf(const std::string& stderrText);

// Status rules shared with the Dask driver (python/cadmedial_batch/job.py):
// timed out -> timeout; allocation failure in stderr or an unexpected SIGKILL
// (the kernel's OOM killer) -> oom; other signals -> crash; non-zero exit ->
// error; else ok.
FileStatus classifyChild(const ChildExit& exit, bool timedOut, const std::string& stderrText);

// The file's message for a non-ok status.
std::string describeFailure(FileStatus status, const ChildExit& exit, double timeoutSeconds,
                            const std::string& stderrText);

}  // namespace cadmedial
