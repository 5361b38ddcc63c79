#include "batch_child.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "cadmedial/errors.hpp"

namespace cadmedial {

namespace {

bool mentionsAllocationFailure(const std::string& text) {
  for (const char* needle : {"bad_alloc", "out of memory", "Out of memory", "OutOfMemory", "Cannot allocate memory"})
    if (text.find(needle) != std::string::npos) return true;
  return false;
}

// Only async-signal-safe calls between fork and exec.
[[noreturn]] void execChild(const char* executable, char* const argv[], const char* stderrPath, double maxMemoryGiB,
                            pid_t parent) {
  ::setpgid(0, 0);
  // Die with the batch even if it is SIGKILLed; if it already died, stop here.
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(127);
  if (maxMemoryGiB > 0) {
    const rlim_t bytes = rlim_t(maxMemoryGiB * 1024.0 * 1024.0 * 1024.0);
    const rlimit limit{bytes, bytes};
    ::setrlimit(RLIMIT_AS, &limit);
  }
  const int devNull = ::open("/dev/null", O_RDWR);
  const int err = ::open(stderrPath, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (devNull < 0 || err < 0) ::_exit(127);
  ::dup2(devNull, STDIN_FILENO);
  ::dup2(devNull, STDOUT_FILENO);
  ::dup2(err, STDERR_FILENO);
  ::execv(executable, argv);
  const char message[] = "error: cannot start the cadmedial executable\n";
  [[maybe_unused]] const ssize_t ignored = ::write(STDERR_FILENO, message, sizeof message - 1);
  ::_exit(127);
}

}  // namespace

pid_t startChild(const std::string& executable, const std::vector<std::string>& arguments,
                 const std::string& stderrPath, double maxMemoryGiB) {
  // Everything the child needs is prepared before fork: no allocation after it.
  std::vector<std::string> args{"cadmedial"};
  args.insert(args.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) throw InputError(kExitProcessingFailed, std::string("fork failed: ") + std::strerror(errno));
  if (pid == 0) execChild(executable.c_str(), argv.data(), stderrPath.c_str(), maxMemoryGiB, parent);
  ::setpgid(pid, pid);  // also here, so a kill(-pid) right after fork finds the group
  return pid;
}

ChildExit decodeChildExit(int waitStatus, long maxRssKiB) {
  ChildExit e;
  if (WIFEXITED(waitStatus)) e.exitCode = WEXITSTATUS(waitStatus);
  if (WIFSIGNALED(waitStatus)) e.signal = WTERMSIG(waitStatus);
  e.peakRssMiB = double(maxRssKiB) / 1024.0;
  return e;
}

std::string errorLineOf(const std::string& text) {
  std::string lastError, lastLine;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    start = end + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    if (line.rfind("error: ", 0) == 0) lastError = line.substr(7);
    lastLine = line;
  }
  std::string line = lastError.empty() ? lastLine : lastError;
  if (line.size() > 500) line = line.substr(0, 497) + "...";
  return line;
}

FileStatus classifyChild(const ChildExit& exit, bool timedOut, const std::string& stderrText) {
  if (timedOut) return FileStatus::Timeout;
  if (exit.exitCode == 0) return FileStatus::Ok;
  if (mentionsAllocationFailure(stderrText) || exit.signal == SIGKILL) return FileStatus::Oom;
  return exit.signal != 0 ? FileStatus::Crash : FileStatus::Error;
}

std::string describeFailure(FileStatus status, const ChildExit& exit, double timeoutSeconds,
                            const std::string& stderrText) {
  std::string line = errorLineOf(stderrText);
  std::string what;
  if (status == FileStatus::Timeout) {
    char text[64];
    std::snprintf(text, sizeof text, "timed out after %g s", timeoutSeconds);
    what = text;
  } else if (exit.signal != 0) {
    const char* name = ::sigabbrev_np(exit.signal);
    what = "killed by SIG" + std::string(name ? name : std::to_string(exit.signal).c_str());
  }
  if (what.empty()) return line;
  return line.empty() ? what : what + ": " + line;
}

}  // namespace cadmedial
