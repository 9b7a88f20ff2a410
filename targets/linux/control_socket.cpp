#include "control_socket.hpp"

#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

namespace costa::host {

ControlSocket::~ControlSocket() {
  if (fd_ >= 0) {
    ::close(fd_);
    ::unlink(path_.c_str());
  }
}

bool ControlSocket::open(const std::string& path, std::string* error) {
  sockaddr_un address{};
  if (path.empty() || path.size() >= sizeof(address.sun_path)) {
    *error = "invalid control socket path '" + path + "'";
    return false;
  }
  fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd_ < 0) {
    const int code = errno;
    *error = "cannot create the control socket: " + std::system_category().message(code);
    return false;
  }
  address.sun_family = AF_UNIX;
  std::memcpy(address.sun_path, path.c_str(), path.size());
  ::unlink(path.c_str());
  // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): the socket API takes sockaddr*
  if (::bind(fd_, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0) {
    const int code = errno;
    *error = "cannot bind the control socket " + path + ": " + std::system_category().message(code);
    ::close(fd_);
    fd_ = -1;
    return false;
  }
  path_ = path;
  return true;
}

void ControlSocket::serve(const std::function<std::string(const std::string&)>& handle) const {
  for (;;) {
    char buffer[512];
    sockaddr_un sender{};
    socklen_t senderLength = sizeof(sender);
    // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): the socket API takes sockaddr*
    auto* senderAddress = reinterpret_cast<sockaddr*>(&sender);
    const ssize_t got =
        ::recvfrom(fd_, buffer, sizeof(buffer) - 1U, 0, senderAddress, &senderLength);
    if (got < 0) {
      return;
    }
    std::string command(buffer, static_cast<size_t>(got));
    while (!command.empty() && (command.back() == '\n' || command.back() == '\r')) {
      command.pop_back();
    }
    const std::string result = handle(command);
    const std::string reply = result.empty() ? "ok" : "error: " + result;
    if (senderLength > sizeof(sa_family_t)) {
      ::sendto(fd_, reply.data(), reply.size(), 0, senderAddress, senderLength);
    }
  }
}

}  // namespace costa::host
