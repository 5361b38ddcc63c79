// Hostile files can make OCCT's translators dereference null handles: a STEP
// file with one misspelt entity name (CARTESIAN_PINT) crashed
// STEPControl_Reader::TransferRoots with SIGSEGV. Inside
// catchingOcctSignals, such a signal becomes an OSD_Signal exception (a
// Standard_Failure) at the nearest OCC_CATCH_SIGNALS: OCCT's own (the
// transfer of one root then fails and the others go on) or the one around
// `work`, which rethrows it to the caller.
#pragma once

#include <functional>

namespace cadmedial {

// Runs `work` with OCCT's handlers for SIGSEGV, SIGBUS, SIGILL, SIGFPE and
// SIGSYS installed (OSD::SetSignal) and puts the process's own handlers back
// afterwards, also when `work` throws. Ctrl-C, SIGHUP and SIGQUIT keep the
// process's handlers throughout. Calls are serialised (signal handlers are
// per process). Only for single-threaded work: a signal in another thread
// finds no OCC_CATCH_SIGNALS there.
void catchingOcctSignals(const std::function<void()>& work);

}  // namespace cadmedial
