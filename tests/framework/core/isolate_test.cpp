// run_isolated (framework/core/isolate.h): whatever the work does in the
// child (returns, throws, crashes, hangs, allocates without end), this
// process gets an answer, in time.
#include "framework/core/isolate.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <csignal>
#include <thread>
#include <vector>

namespace cooperage {
namespace {

using Outcome = IsolatedRun::Outcome;

TEST(Isolate, ReturnsTheBytesTheWorkProduced) {
  const IsolatedRun r = run_isolated(
      [](std::string& out) { out = std::string(1 << 20, 'x') + "end"; }, IsolationLimits{10, 0});
  ASSERT_EQ(r.outcome, Outcome::Done);
  EXPECT_EQ(r.payload.size(), (1u << 20) + 3);
  EXPECT_EQ(r.payload.substr(r.payload.size() - 3), "end");
}

TEST(Isolate, AMeshingErrorComesBackWithItsCodeAndMessage) {
  const IsolatedRun r = run_isolated(
      [](std::string&) { throw MeshingError(ErrorCode::ParseError, "part.step: not a STEP file"); },
      IsolationLimits{10, 0});
  ASSERT_EQ(r.outcome, Outcome::Failed);
  EXPECT_EQ(r.code, ErrorCode::ParseError);
  EXPECT_EQ(r.payload, "part.step: not a STEP file");
  EXPECT_EQ(r.describe({}), "part.step: not a STEP file");
}

TEST(Isolate, ACrashIsReportedWithItsSignal) {
  const IsolatedRun r =
      run_isolated([](std::string&) { std::raise(SIGSEGV); }, IsolationLimits{10, 0});
  ASSERT_EQ(r.outcome, Outcome::Crashed);
  EXPECT_EQ(r.signal, SIGSEGV);
  EXPECT_EQ(r.describe({}), "it crashed (signal 11, SIGSEGV)");
}

TEST(Isolate, AHangIsKilledAtTheTimeLimit) {
  const auto t0 = std::chrono::steady_clock::now();
  const IsolatedRun r = run_isolated(
      [](std::string&) {
        for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
      },
      IsolationLimits{0.5, 0});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(r.outcome, Outcome::TimedOut);
  EXPECT_LT(seconds, 5.0);
  EXPECT_EQ(r.describe(IsolationLimits{0.5, 0}), "it did not finish within 0.5 s");
}

TEST(Isolate, RunawayAllocationStopsAtTheMemoryLimit) {
  const IsolatedRun r = run_isolated(
      [](std::string&) {
        std::vector<std::vector<char>> hog;
        for (;;) hog.emplace_back(std::size_t{64} << 20, 'x');
      },
      IsolationLimits{30, std::size_t{256} << 20});
  ASSERT_EQ(r.outcome, Outcome::OutOfMemory) << r.describe({});
}

TEST(Isolate, TheChildsOutputDoesNotReachThisProcess) {
  // Kernels print on stdout; the child's stdout is /dev/null.
  testing::internal::CaptureStdout();
  const IsolatedRun r = run_isolated(
      [](std::string& out) {
        std::printf("noise from a kernel\n");
        std::fflush(stdout);
        out = "ok";
      },
      IsolationLimits{10, 0});
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  EXPECT_EQ(r.payload, "ok");
}

TEST(Isolate, AComputingLoopIsStoppedByTheProcessorTimeLimit) {
  const auto t0 = std::chrono::steady_clock::now();
  IsolationLimits limits;
  limits.seconds = 60;  // the wall clock would wait much longer
  limits.cpu_seconds = 1;
  const IsolatedRun r = run_isolated(
      [](std::string&) {
        volatile unsigned long x = 0;
        for (;;) x = x + 1;
      },
      limits);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(r.outcome, Outcome::TimedOut);
  EXPECT_TRUE(r.cpu);
  EXPECT_LT(seconds, 30.0);  // 1 s of processor time, whatever else the machine runs
  EXPECT_EQ(r.describe(limits), "it used more than 1 s of processor time");
}

TEST(Isolate, WaitingIsNotChargedAsProcessorTime) {
  // A child that sleeps 2 s under a 1-s processor-time limit finishes: only
  // computing counts, so a slow (busy) machine does not fail a valid file.
  IsolationLimits limits;
  limits.seconds = 60;
  limits.cpu_seconds = 1;
  const IsolatedRun r = run_isolated(
      [](std::string& out) {
        std::this_thread::sleep_for(std::chrono::seconds(2));
        out = "done";
      },
      limits);
  ASSERT_EQ(r.outcome, Outcome::Done);
  EXPECT_EQ(r.payload, "done");
}

}  // namespace
}  // namespace cooperage
