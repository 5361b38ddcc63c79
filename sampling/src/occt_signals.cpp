// OCC_CATCH_SIGNALS is a setjmp only where OCC_CONVERT_SIGNALS is defined
// before OCCT's headers (Standard_ErrorHandler.hxx); Debian's OCCT is built
// with it, so its signal handler longjmps to that point.
#define OCC_CONVERT_SIGNALS
#include "occt_signals.hpp"

#include <array>
#include <cfenv>
#include <csignal>
#include <mutex>

#include <pthread.h>

#include <OSD.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>

namespace cadmedial {

namespace {

// Every signal OSD::SetSignal takes over on Linux, and of those the ones a
// crash raises (the others a user sends: they keep the process's handling).
constexpr std::array<int, 8> kOsdSignals = {SIGHUP, SIGINT, SIGQUIT, SIGILL, SIGBUS, SIGFPE, SIGSEGV, SIGSYS};
constexpr std::array<int, 5> kCrashSignals = {SIGILL, SIGBUS, SIGFPE, SIGSEGV, SIGSYS};

template <std::size_t N>
std::array<struct sigaction, N> currentActions(const std::array<int, N>& signals) {
  std::array<struct sigaction, N> actions{};
  for (std::size_t i = 0; i < N; ++i) sigaction(signals[i], nullptr, &actions[i]);
  return actions;
}

template <std::size_t N>
void install(const std::array<int, N>& signals, const std::array<struct sigaction, N>& actions) {
  for (std::size_t i = 0; i < N; ++i) sigaction(signals[i], &actions[i], nullptr);
}

// OCCT's handlers for the crash signals, read once: OSD::SetSignal installs
// all eight (and sets the FP environment), everything is put back at once.
const std::array<struct sigaction, kCrashSignals.size()>& occtCrashHandlers() {
  static const auto handlers = [] {
    const auto own = currentActions(kOsdSignals);
    std::fenv_t fpu;
    std::fegetenv(&fpu);
    OSD::SetSignal(OSD_SignalMode_Set, /*theFloatingSignal=*/false);
    const auto occt = currentActions(kCrashSignals);
    install(kOsdSignals, own);
    std::fesetenv(&fpu);
    return occt;
  }();
  return handlers;
}

// The process's state that the work may change: the crash signals'
// handlers, this thread's signal mask (OCCT's SIGILL and SIGSYS handlers
// longjmp out with the signal still blocked) and the FP environment.
class SavedState {
 public:
  SavedState() : handlers_(currentActions(kCrashSignals)) {
    pthread_sigmask(SIG_SETMASK, nullptr, &mask_);
    std::fegetenv(&fpu_);
  }
  ~SavedState() {
    install(kCrashSignals, handlers_);
    pthread_sigmask(SIG_SETMASK, &mask_, nullptr);
    std::fesetenv(&fpu_);
  }
  SavedState(const SavedState&) = delete;
  SavedState& operator=(const SavedState&) = delete;

 private:
  std::array<struct sigaction, kCrashSignals.size()> handlers_;
  sigset_t mask_{};
  std::fenv_t fpu_{};
};

// The setjmp frame: a signal during `work` that no inner OCC_CATCH_SIGNALS
// takes returns here and is rethrown as the OSD_Signal exception recorded.
void runWithHandler(const std::function<void()>& work) {
  OCC_CATCH_SIGNALS
  work();
}

}  // namespace

void catchingOcctSignals(const std::function<void()>& work) {
  static std::mutex oneAtATime;
  const std::lock_guard<std::mutex> lock(oneAtATime);
  const auto& occt = occtCrashHandlers();
  const SavedState saved;
  install(kCrashSignals, occt);
  runWithHandler(work);
}

}  // namespace cadmedial
