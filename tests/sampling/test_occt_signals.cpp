// catchingOcctSignals: OCCT's signal handlers only while the work runs, the
// process's own before and after, and Ctrl-C never taken over.
#include <gtest/gtest.h>

#include <csignal>
#include <stdexcept>

#include <pthread.h>

#include <Standard_Failure.hxx>

#include "occt_signals.hpp"

namespace cadmedial {
namespace {

void ownHandler(int) {}

using Handler = void (*)(int);
Handler handlerOf(int signal) {
  struct sigaction now {};
  sigaction(signal, nullptr, &now);
  return now.sa_handler;
}

// Installs ownHandler for SIGSEGV and SIGINT for the test's duration.
class OcctSignals : public ::testing::Test {
 protected:
  void SetUp() override {
    struct sigaction own {};
    own.sa_handler = ownHandler;
    sigemptyset(&own.sa_mask);
    sigaction(SIGSEGV, &own, &savedSegv_);
    sigaction(SIGINT, &own, &savedInt_);
  }
  void TearDown() override {
    sigaction(SIGSEGV, &savedSegv_, nullptr);
    sigaction(SIGINT, &savedInt_, nullptr);
  }
  struct sigaction savedSegv_ {}, savedInt_ {};
};

TEST_F(OcctSignals, HandlersAreOcctsOnlyWhileTheWorkRuns) {
  Handler segvDuring = nullptr, intDuring = nullptr;
  catchingOcctSignals([&] {
    segvDuring = handlerOf(SIGSEGV);
    intDuring = handlerOf(SIGINT);
  });
  EXPECT_NE(segvDuring, &ownHandler);  // OCCT's, to turn a crash into an exception
  EXPECT_EQ(intDuring, &ownHandler);   // Ctrl-C stays the process's
  EXPECT_EQ(handlerOf(SIGSEGV), &ownHandler);
  EXPECT_EQ(handlerOf(SIGINT), &ownHandler);
}

TEST_F(OcctSignals, HandlersComeBackWhenTheWorkThrows) {
  EXPECT_THROW(catchingOcctSignals([] { throw std::runtime_error("bad file"); }), std::runtime_error);
  EXPECT_EQ(handlerOf(SIGSEGV), &ownHandler);
  EXPECT_EQ(handlerOf(SIGINT), &ownHandler);
}

bool blockedHere(int signal) {
  sigset_t mask;
  pthread_sigmask(SIG_SETMASK, nullptr, &mask);
  return sigismember(&mask, signal) == 1;
}

// A crash inside the work comes out as OCCT's exception, every time (OCCT's
// SIGILL and SIGSYS handlers leave their signal blocked: a second one would
// have killed the process), and the process's handlers come back.
TEST_F(OcctSignals, ACrashInTheWorkIsAnExceptionEveryTime) {
  for (int signal : {SIGSEGV, SIGILL, SIGSEGV, SIGILL, SIGFPE, SIGBUS}) {
    EXPECT_THROW(catchingOcctSignals([signal] { std::raise(signal); }), Standard_Failure) << signal;
    EXPECT_FALSE(blockedHere(signal)) << signal;
  }
  EXPECT_EQ(handlerOf(SIGSEGV), &ownHandler);
  EXPECT_EQ(handlerOf(SIGINT), &ownHandler);
}

}  // namespace
}  // namespace cadmedial
