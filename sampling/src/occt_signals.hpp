// Hostile files can make OCCT's translators dereference null handles: a STEP
// file with one misspelt entity name (CARTESIAN_PINT) crashed
// STEPControl_Reader::TransferRoots with SIGSEGV. Inside
// catchingOcctSignals, such a signal becomes an OSD_Signal exception (a
// Standard_Failure) at the nearest OCC_CATCH_SIGNALS: OCCT's own (the
// transfer of one root then fails and the others go on), the readers' (set
// up after their locals, so those are destroyed as the exception leaves), or
// the one around `work`, which rethrows it to the caller.
#pragma once

#include <functional>

namespace cadmedial {

// Runs `work` with OCCT's handlers for SIGSEGV, SIGBUS, SIGILL, SIGFPE and
// SIGSYS installed and puts the process's own handlers, signal mask and
// floating-point environment back afterwards, also when `work` throws.
// Ctrl-C, SIGHUP and SIGQUIT are never taken over (OCCT's handlers for them
// are installed once, read, and removed at once). Calls are serialised
// (signal handlers are per process). A crash in ANOTHER thread while `work`
// runs meets OCCT's handler with no OCC_CATCH_SIGNALS in that thread: OCCT
// prints "*** Abort ***" and exits with 1 instead of the usual crash.
void catchingOcctSignals(const std::function<void()>& work);

}  // namespace cadmedial
