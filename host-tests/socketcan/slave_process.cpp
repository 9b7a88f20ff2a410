#include "slave_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

namespace costa::test {

SlaveProcess::SlaveProcess(const std::vector<std::string>& arguments) {
  char logTemplate[] = "/tmp/costa-slave-log-XXXXXX";
  const int logFd = ::mkstemp(logTemplate);
  logPath_ = logTemplate;
  std::vector<std::string> all = {COSTA_SLAVE_PATH};
  all.insert(all.end(), arguments.begin(), arguments.end());
  pid_ = ::fork();
  if (pid_ == 0) {
    ::dup2(logFd, STDOUT_FILENO);
    ::dup2(logFd, STDERR_FILENO);
    std::vector<char*> argv;
    for (std::string& argument : all) {
      argv.push_back(argument.data());
    }
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  ::close(logFd);
}

SlaveProcess::~SlaveProcess() {
  if (pid_ > 0) {
    stop(SIGKILL);
  }
  ::unlink(logPath_.c_str());
}

int SlaveProcess::waitExit(int timeoutMs) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs);
  while (pid_ > 0) {
    int status = 0;
    const pid_t done = ::waitpid(pid_, &status, WNOHANG);
    if (done == pid_) {
      pid_ = -1;
      return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    if (std::chrono::steady_clock::now() >= end) {
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return -1;
}

int SlaveProcess::stop(int signal) {
  if (pid_ <= 0) {
    return -1;
  }
  ::kill(pid_, signal);
  const int status = waitExit(kSlaveExitTimeoutMs);
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    waitExit(kSlaveExitTimeoutMs);
  }
  return status;
}

std::string SlaveProcess::output() const {
  std::ifstream file(logPath_);
  std::stringstream content;
  content << file.rdbuf();
  return content.str();
}

}  // namespace costa::test
