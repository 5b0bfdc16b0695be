// run_isolated (framework/core/isolate.h): whatever the work does in the
// child (returns, throws, crashes, hangs, allocates without end), this
// process gets an answer, in time.
#include "framework/core/isolate.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <csignal>
#include <thread>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

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

// Two files as a handshake: the child makes one and waits for the other,
// which only the parent's waiting task makes, after it has seen the first.
// So the task runs in this process while the child runs (neither before
// the fork nor after the child ended, which would leave each side waiting).
TEST(Isolate, TheWaitingTaskRunsHereWhileTheChildWorks) {
  const std::string dir = ::testing::TempDir();
  const std::string from_child = dir + "/isolate_child_" + std::to_string(::getpid());
  const std::string from_parent = dir + "/isolate_parent_" + std::to_string(::getpid());
  std::remove(from_child.c_str());
  std::remove(from_parent.c_str());
  const auto appears = [](const std::string& path) {
    for (int k = 0; k < 2000; ++k) {  // up to 20 s
      if (std::FILE* f = std::fopen(path.c_str(), "r")) {
        std::fclose(f);
        return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  };
  const pid_t parent = ::getpid();
  pid_t ran_in = 0;
  bool saw_child = false;
  const IsolatedRun r = run_isolated(
      [&](std::string& out) {
        std::fclose(std::fopen(from_child.c_str(), "w"));
        out = appears(from_parent) ? "saw the parent" : "alone";
      },
      IsolationLimits{60, 0},
      [&] {
        ran_in = ::getpid();
        saw_child = appears(from_child);
        std::fclose(std::fopen(from_parent.c_str(), "w"));
      });
  std::remove(from_child.c_str());
  std::remove(from_parent.c_str());
  ASSERT_EQ(r.outcome, Outcome::Done);
  EXPECT_EQ(r.payload, "saw the parent");
  EXPECT_EQ(ran_in, parent);
  EXPECT_TRUE(saw_child);
}

TEST(Isolate, TheWaitingTasksErrorComesOutAfterTheChildIsReaped) {
  bool thrown = false;
  try {
    run_isolated([](std::string& out) { out = "done"; }, IsolationLimits{10, 0},
                 [] { throw MeshingError(ErrorCode::Internal, "cannot load the library"); });
  } catch (const MeshingError& e) {
    thrown = true;
    EXPECT_NE(std::string(e.what()).find("cannot load the library"), std::string::npos);
  }
  EXPECT_TRUE(thrown);
  // No child is left behind: nothing more to wait for.
  int status = 0;
  EXPECT_EQ(::waitpid(-1, &status, WNOHANG), -1);
}

}  // namespace
}  // namespace cooperage
