// costa-slave run as a child process for tests.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace costa::test {

/// Milliseconds to wait for costa-slave to exit or to answer on its control socket. Generous,
/// like kSocketReceiveTimeoutMs: a sanitized slave in the emulated vcan machine on a busy host
/// takes seconds to start; a passing test never waits this long.
inline constexpr int kSlaveExitTimeoutMs = 20000;

class SlaveProcess {
 public:
  /// Starts COSTA_SLAVE_PATH with `arguments`; stdout and stderr go to a log file.
  explicit SlaveProcess(const std::vector<std::string>& arguments);
  ~SlaveProcess();
  SlaveProcess(const SlaveProcess&) = delete;
  SlaveProcess& operator=(const SlaveProcess&) = delete;

  /// Sends `signal` and waits (up to kSlaveExitTimeoutMs) for the exit; returns the exit
  /// status, or -1 if it did not exit normally.
  int stop(int signal);
  /// Waits up to `timeoutMs` for the process to exit by itself; -1 if still running.
  int waitExit(int timeoutMs);
  bool running() const { return pid_ > 0; }
  /// Everything the process printed so far.
  std::string output() const;

 private:
  pid_t pid_ = -1;
  std::string logPath_;
};

}  // namespace costa::test
