#include "raw_socket.hpp"

#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/uio.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace costa::test {

std::string testInterface() {
  const char* name = std::getenv("COSTA_TEST_IFACE");
  return name != nullptr && *name != '\0' ? name : "vcan0";
}

RawCanSocket::~RawCanSocket() {
  if (fd_ >= 0) {
    ::close(fd_);
  }
}

bool RawCanSocket::open(const std::string& interfaceName, std::string* error) {
  fd_ = ::socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC, CAN_RAW);
  if (fd_ < 0) {
    *error = std::string("socket(PF_CAN): ") + std::strerror(errno);
    return false;
  }
  sockaddr_can address{};
  address.can_family = AF_CAN;
  address.can_ifindex = static_cast<int>(if_nametoindex(interfaceName.c_str()));
  if (address.can_ifindex == 0 ||
      ::bind(fd_, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0) {
    *error = "cannot bind to " + interfaceName + ": " + std::strerror(errno);
    return false;
  }
  const int on = 1;  // every received frame carries the time it went onto the interface
  if (::setsockopt(fd_, SOL_SOCKET, SO_TIMESTAMPNS, &on, sizeof(on)) != 0) {
    *error = std::string("setsockopt(SO_TIMESTAMPNS): ") + std::strerror(errno);
    return false;
  }
  return true;
}

bool RawCanSocket::send(const CanFrame& frame) {
  can_frame raw{};
  raw.can_id = frame.extended ? (frame.id | CAN_EFF_FLAG) : frame.id;
  if (frame.rtr) {
    raw.can_id |= CAN_RTR_FLAG;
  }
  raw.len = frame.dlc;
  std::memcpy(raw.data, frame.data, 8);
  return ::write(fd_, &raw, sizeof(raw)) == static_cast<ssize_t>(sizeof(raw));
}

bool RawCanSocket::sendErrorFrame(uint32_t errorClass, uint8_t controller) {
  can_frame raw{};
  raw.can_id = CAN_ERR_FLAG | (errorClass & CAN_ERR_MASK);
  raw.len = CAN_ERR_DLC;
  raw.data[1] = controller;
  return ::write(fd_, &raw, sizeof(raw)) == static_cast<ssize_t>(sizeof(raw));
}

namespace {

/// The moment `stamp` (CLOCK_REALTIME, as the kernel stamps frames) on the steady clock.
std::chrono::steady_clock::time_point onSteadyClock(const timespec& stamp) {
  const auto now = std::chrono::system_clock::now();
  const auto steadyNow = std::chrono::steady_clock::now();
  const auto at = std::chrono::system_clock::time_point(
      std::chrono::duration_cast<std::chrono::system_clock::duration>(
          std::chrono::seconds(stamp.tv_sec) + std::chrono::nanoseconds(stamp.tv_nsec)));
  const auto age = std::chrono::duration_cast<std::chrono::steady_clock::duration>(now - at);
  return age > std::chrono::steady_clock::duration::zero() ? steadyNow - age : steadyNow;
}

}  // namespace

bool RawCanSocket::receive(CanFrame* frame, int timeoutMs,
                           std::chrono::steady_clock::time_point* onBus) {
  pollfd descriptor{fd_, POLLIN, 0};
  if (::poll(&descriptor, 1, timeoutMs) <= 0) {
    return false;
  }
  can_frame raw{};
  iovec data{&raw, sizeof(raw)};
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(timespec))];
  msghdr message{};
  message.msg_iov = &data;
  message.msg_iovlen = 1;
  message.msg_control = control;
  message.msg_controllen = sizeof(control);
  if (::recvmsg(fd_, &message, 0) != static_cast<ssize_t>(sizeof(raw))) {
    return false;
  }
  if (onBus != nullptr) {
    *onBus = std::chrono::steady_clock::now();
    for (cmsghdr* header = CMSG_FIRSTHDR(&message); header != nullptr;
         header = CMSG_NXTHDR(&message, header)) {
      if (header->cmsg_level == SOL_SOCKET && header->cmsg_type == SCM_TIMESTAMPNS) {
        timespec stamp{};
        std::memcpy(&stamp, CMSG_DATA(header), sizeof(stamp));
        *onBus = onSteadyClock(stamp);
      }
    }
  }
  *frame = CanFrame{};
  frame->extended = (raw.can_id & CAN_EFF_FLAG) != 0U;
  frame->rtr = (raw.can_id & CAN_RTR_FLAG) != 0U;
  frame->id = raw.can_id & (frame->extended ? CAN_EFF_MASK : CAN_SFF_MASK);
  frame->dlc = raw.len;
  if (!frame->rtr) {
    std::memcpy(frame->data, raw.data, raw.len);
  }
  return true;
}

}  // namespace costa::test
