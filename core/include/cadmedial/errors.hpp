// Errors a user can act on, with the exit code the command line maps them to.
#pragma once

#include <stdexcept>
#include <string>

namespace cadmedial {

// Exit codes of the `cadmedial` command (documented in the README).
enum ExitCode : int {
  kExitOk = 0,
  kExitProcessingFailed = 1,  // the input was read but a stage failed
  kExitUsage = 2,             // bad command line
  kExitUnreadableInput = 3,   // missing, empty, truncated or not a CAD file
  kExitNoSolid = 4,           // readable, but no closed solid in it
  kExitOutputFailed = 5,      // outputs could not be written
};

// An error in the input file, reported to the user as one line.
class InputError : public std::runtime_error {
 public:
  InputError(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

}  // namespace cadmedial
