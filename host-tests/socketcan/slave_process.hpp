// costa-slave run as a child process for tests.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace costa::test {

class SlaveProcess {
 public:
  /// Starts COSTA_SLAVE_PATH with `arguments`; stdout and stderr go to a log file.
  explicit SlaveProcess(const std::vector<std::string>& arguments);
  ~SlaveProcess();
  SlaveProcess(const SlaveProcess&) = delete;
  SlaveProcess& operator=(const SlaveProcess&) = delete;

  /// Sends `signal` and waits (up to 5 s) for the exit; returns the exit status, or -1 if it
  /// did not exit normally.
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
