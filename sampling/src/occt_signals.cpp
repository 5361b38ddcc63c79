// OCC_CATCH_SIGNALS is a setjmp only where OCC_CONVERT_SIGNALS is defined
// before OCCT's headers (Standard_ErrorHandler.hxx); Debian's OCCT is built
// with it, so its signal handler longjmps to that point.
#define OCC_CONVERT_SIGNALS
#include "occt_signals.hpp"

#include <array>
#include <csignal>
#include <mutex>

#include <OSD.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>

namespace cadmedial {

namespace {

// Every signal OSD::SetSignal takes over on Linux.
constexpr std::array<int, 8> kOsdSignals = {SIGHUP, SIGINT, SIGQUIT, SIGILL, SIGBUS, SIGFPE, SIGSEGV, SIGSYS};
// Those a user sends on purpose: they keep the process's own handling.
constexpr std::array<int, 3> kInteractiveSignals = {SIGHUP, SIGINT, SIGQUIT};

class SavedHandlers {
 public:
  SavedHandlers() {
    for (std::size_t i = 0; i < kOsdSignals.size(); ++i) sigaction(kOsdSignals[i], nullptr, &saved_[i]);
  }
  ~SavedHandlers() { restore(kOsdSignals); }
  template <std::size_t N>
  void restore(const std::array<int, N>& signals) const {
    for (int s : signals)
      for (std::size_t i = 0; i < kOsdSignals.size(); ++i)
        if (kOsdSignals[i] == s) sigaction(s, &saved_[i], nullptr);
  }

 private:
  std::array<struct sigaction, kOsdSignals.size()> saved_{};
};

// The setjmp frame: a signal during `work` returns here and is rethrown as
// the OSD_Signal exception the handler recorded.
void runWithHandler(const std::function<void()>& work) {
  OCC_CATCH_SIGNALS
  work();
}

}  // namespace

void catchingOcctSignals(const std::function<void()>& work) {
  static std::mutex oneAtATime;
  const std::lock_guard<std::mutex> lock(oneAtATime);
  const SavedHandlers saved;
  OSD::SetSignal(OSD_SignalMode_Set, /*theFloatingSignal=*/false);
  saved.restore(kInteractiveSignals);
  runWithHandler(work);
}

}  // namespace cadmedial
