#include "framework/core/isolate.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace cooperage {
namespace {

// The child's report: one tag byte, then the payload.
constexpr char kDone = 'D';
constexpr char kFailed = 'E';
constexpr char kOutOfMemory = 'M';

void write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent is gone or gave up; nothing to do
    data += n;
    size -= static_cast<std::size_t>(n);
  }
}

/// Current size of this process's address space (VmSize), 0 if unknown.
std::size_t address_space_in_use() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return 0;
  unsigned long pages = 0;
  const int got = std::fscanf(f, "%lu", &pages);
  std::fclose(f);
  return got == 1 ? pages * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE)) : 0;
}

[[noreturn]] void child_main(int fd, const std::function<void(std::string&)>& work,
                             const IsolationLimits& limits) {
  // Quiet, no core files left behind, bounded memory.
  const int null_fd = ::open("/dev/null", O_WRONLY);
  if (null_fd >= 0) {
    ::dup2(null_fd, STDOUT_FILENO);
    ::dup2(null_fd, STDERR_FILENO);
    ::close(null_fd);
  }
  const rlimit no_core{0, 0};
  ::setrlimit(RLIMIT_CORE, &no_core);
  if (limits.cpu_seconds > 0) {
    // SIGXCPU at the soft limit (fatal: no handler, no core), SIGKILL soon after.
    const rlim_t soft = static_cast<rlim_t>(std::ceil(std::min(limits.cpu_seconds, 1e7)));
    const rlimit cpu{soft, soft + 2};
    ::setrlimit(RLIMIT_CPU, &cpu);
  }
  if (limits.memory_bytes > 0) {
    const rlim_t cap = static_cast<rlim_t>(address_space_in_use() + limits.memory_bytes);
    const rlimit as{cap, cap};
    ::setrlimit(RLIMIT_AS, &as);
  }
  std::string out;
  char tag = kDone;
  try {
    work(out);
  } catch (const MeshingError& e) {
    tag = kFailed;
    out = std::string(1, static_cast<char>(e.code())) + e.what();
  } catch (const std::bad_alloc&) {
    tag = kOutOfMemory;
    out.clear();
  } catch (const std::exception& e) {
    tag = kFailed;
    out = std::string(1, static_cast<char>(ErrorCode::Internal)) + e.what();
  } catch (...) {
    tag = kFailed;
    out = std::string(1, static_cast<char>(ErrorCode::Internal)) + "unknown exception";
  }
  write_all(fd, &tag, 1);
  write_all(fd, out.data(), out.size());
  ::close(fd);
  ::_exit(0);  // no atexit handlers, no static destructors of the parent's state
}

const char* signal_name(int sig) {
  switch (sig) {
    case SIGSEGV: return "SIGSEGV";
    case SIGBUS: return "SIGBUS";
    case SIGFPE: return "SIGFPE";
    case SIGILL: return "SIGILL";
    case SIGABRT: return "SIGABRT";
    case SIGKILL: return "SIGKILL";
    case SIGXCPU: return "SIGXCPU";
    default: return nullptr;
  }
}

std::string bytes_text(std::size_t bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g GB", static_cast<double>(bytes) / 1e9);
  return buf;
}

}  // namespace

std::string IsolatedRun::describe(const IsolationLimits& limits) const {
  switch (outcome) {
    case Outcome::Done: return {};
    case Outcome::Failed: return payload;
    case Outcome::Crashed: {
      if (signal == 0) return "it stopped without a result";
      const char* name = signal_name(signal);
      return "it crashed (signal " + std::to_string(signal) +
             (name ? std::string(", ") + name : std::string()) + ")";
    }
    case Outcome::TimedOut: {
      char buf[80];
      if (cpu) {
        std::snprintf(buf, sizeof buf, "it used more than %g s of processor time",
                      std::ceil(limits.cpu_seconds));
      } else {
        std::snprintf(buf, sizeof buf, "it did not finish within %g s", limits.seconds);
      }
      return buf;
    }
    case Outcome::OutOfMemory:
      return "it needed more than " + bytes_text(limits.memory_bytes) + " of memory";
  }
  return {};
}

namespace {

IsolatedRun fork_and_wait(const std::function<void(std::string& out)>& work,
                          const IsolationLimits& limits, const std::function<void()>& while_waiting,
                          std::exception_ptr& waiting_error) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0)
    throw MeshingError(ErrorCode::Internal, std::string("pipe: ") + std::strerror(errno));
  std::fflush(nullptr);  // the child must not flush our buffered output again
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int err = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    throw MeshingError(ErrorCode::Internal, std::string("fork: ") + std::strerror(err));
  }
  if (pid == 0) {
    ::close(fds[0]);
    child_main(fds[1], work, limits);
  }
  ::close(fds[1]);
  if (while_waiting) {
    try {
      while_waiting();
    } catch (...) {
      waiting_error = std::current_exception();
    }
  }

  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::milliseconds(static_cast<long long>(
                                           std::clamp(limits.seconds, 0.0, 1e7) * 1000.0));
  std::string received;
  bool timed_out = false;
  char buf[1 << 16];
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // EOF: the child closed its end (or died)
    received.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);

  IsolatedRun run;
  int status = 0;
  if (timed_out) {
    ::kill(pid, SIGKILL);
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    run.outcome = IsolatedRun::Outcome::TimedOut;
    return run;
  }
  // EOF came; the child is exiting. Give it until the deadline, then kill it.
  rusage usage{};
  for (;;) {
    const pid_t r = ::wait4(pid, &status, WNOHANG, &usage);
    if (r == pid) break;
    if (r < 0 && errno != EINTR) break;
    if (Clock::now() >= deadline) {
      ::kill(pid, SIGKILL);
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      run.outcome = IsolatedRun::Outcome::TimedOut;
      return run;
    }
    ::usleep(1000);
  }
  const double cpu_used =
      static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
      1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  if (WIFSIGNALED(status) && limits.cpu_seconds > 0 &&
      (WTERMSIG(status) == SIGXCPU ||
       (WTERMSIG(status) == SIGKILL && cpu_used >= std::floor(limits.cpu_seconds)))) {
    run.outcome = IsolatedRun::Outcome::TimedOut;
    run.cpu = true;
    return run;
  }
  if (WIFSIGNALED(status)) {
    run.outcome = IsolatedRun::Outcome::Crashed;
    run.signal = WTERMSIG(status);
    return run;
  }
  if (received.empty()) {
    run.outcome = IsolatedRun::Outcome::Crashed;
    return run;
  }
  const char tag = received[0];
  if (tag == kDone) {
    run.outcome = IsolatedRun::Outcome::Done;
    run.payload = received.substr(1);
  } else if (tag == kOutOfMemory) {
    run.outcome = IsolatedRun::Outcome::OutOfMemory;
  } else if (tag == kFailed && received.size() >= 2) {
    run.outcome = IsolatedRun::Outcome::Failed;
    const int code = static_cast<unsigned char>(received[1]);
    run.code = code <= static_cast<int>(ErrorCode::Internal) ? static_cast<ErrorCode>(code)
                                                             : ErrorCode::Internal;
    run.payload = received.substr(2);
  }
  return run;
}

}  // namespace

bool single_threaded() {
  // /proc/self/stat: "pid (comm) state ..." with num_threads the 20th field;
  // comm may hold spaces and parentheses, so count from the last ')'.
  FILE* f = std::fopen("/proc/self/stat", "r");
  if (f == nullptr) return false;
  char buf[1024];
  const size_t n = std::fread(buf, 1, sizeof buf - 1, f);
  std::fclose(f);
  buf[n] = '\0';
  const char* p = std::strrchr(buf, ')');
  if (p == nullptr) return false;
  long threads = 0;
  // After ')': state (field 3) ... num_threads (field 20): 17 fields to skip.
  int field = 2;
  for (const char* c = p + 1; *c != '\0'; ++c) {
    if (*c != ' ') continue;
    if (++field == 20) {
      threads = std::strtol(c + 1, nullptr, 10);
      break;
    }
  }
  return threads == 1;
}

IsolatedRun run_isolated(const std::function<void(std::string& out)>& work,
                         const IsolationLimits& limits,
                         const std::function<void()>& while_waiting) {
  std::exception_ptr waiting_error;
  IsolatedRun run = fork_and_wait(work, limits, while_waiting, waiting_error);
  if (waiting_error) std::rethrow_exception(waiting_error);
  return run;
}

}  // namespace cooperage
