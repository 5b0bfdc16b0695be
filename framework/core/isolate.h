// Running untrusted work (a CAD kernel reading a damaged file, libnetcdf
// opening one) in a child process, so that a crash, a hang or a runaway
// allocation there becomes an error here (issue 21 items 1-2). The child is
// a fork() of this process: `work` sees all of its memory, and hands back
// bytes through a pipe.
#pragma once

#include "framework/core/error.h"

#include <cstddef>
#include <functional>
#include <string>

namespace cooperage {

struct IsolationLimits {
  double seconds = 60;           ///< wall-clock limit; the child is killed after it
  std::size_t memory_bytes = 0;  ///< extra address space the child may take (0: no limit)
  /// Processor time the child may use (0: no limit). Unlike the wall-clock
  /// limit it does not shrink when the machine is busy: a valid file is not
  /// refused because other work slowed its reading, while a kernel loop
  /// still ends after this much computing.
  double cpu_seconds = 0;
};

/// How an isolated piece of work ended.
struct IsolatedRun {
  enum class Outcome {
    Done,         ///< work returned; `payload` holds the bytes it produced
    Failed,       ///< work threw; `code` and `payload` (the message) say why
    Crashed,      ///< the child died of `signal` (or exited without a word)
    TimedOut,     ///< killed after IsolationLimits::seconds (or cpu_seconds: `cpu`)
    OutOfMemory,  ///< an allocation failed under IsolationLimits::memory_bytes
  };
  Outcome outcome = Outcome::Crashed;
  std::string payload;
  ErrorCode code = ErrorCode::Internal;
  int signal = 0;
  bool cpu = false;  ///< TimedOut by the processor-time limit, not the wall clock

  /// A clause for a person: "it crashed (signal 11, SIGSEGV)", "it did not
  /// finish within 30 s", "it needed more than 2 GB of memory"; "" for Done.
  std::string describe(const IsolationLimits& limits) const;
};

/// True when this process runs one thread (/proc/self/stat), so that the
/// child of a fork may run the dynamic loader: no other thread can have
/// held its lock at the fork. False when that cannot be read.
bool single_threaded();

/// Runs `work(out)` in a forked child: stdout and stderr of the child go to
/// /dev/null (kernels print), core dumps are off, the address space is
/// capped when asked. A MeshingError thrown by `work` comes back as Failed
/// with its code and message; any other exception as Failed(Internal).
/// Never throws for what happens in the child; throws MeshingError(Internal)
/// only when the process cannot fork or make a pipe.
/// Do not call it while other threads of this process hold locks the work
/// needs (only the calling thread exists in the child).
/// `while_waiting` (optional) runs in this process right after the fork,
/// before the wait: work the caller needs anyway, done while the child
/// works. An exception from it is thrown once the child is reaped.
IsolatedRun run_isolated(const std::function<void(std::string& out)>& work,
                         const IsolationLimits& limits,
                         const std::function<void()>& while_waiting = {});

}  // namespace cooperage
