// costa-slave --control PATH: a UNIX datagram socket on which outside tools send simulation
// commands (one per datagram) and receive "ok" or "error: <why>".
#pragma once

#include <functional>
#include <string>

namespace costa::host {

class ControlSocket {
 public:
  ControlSocket() = default;
  ~ControlSocket();
  ControlSocket(const ControlSocket&) = delete;
  ControlSocket& operator=(const ControlSocket&) = delete;

  /// Creates the socket at `path` (replacing a stale one). False with `error` on failure.
  bool open(const std::string& path, std::string* error);
  int fd() const { return fd_; }

  /// Reads waiting commands, answers each with `handle(command)` ("" = ok).
  void serve(const std::function<std::string(const std::string&)>& handle) const;

 private:
  int fd_ = -1;
  std::string path_;
};

}  // namespace costa::host
