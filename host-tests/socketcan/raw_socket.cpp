#include "raw_socket.hpp"

#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <poll.h>
#include <sys/socket.h>
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

bool RawCanSocket::receive(CanFrame* frame, int timeoutMs) {
  pollfd descriptor{fd_, POLLIN, 0};
  if (::poll(&descriptor, 1, timeoutMs) <= 0) {
    return false;
  }
  can_frame raw{};
  if (::read(fd_, &raw, sizeof(raw)) != static_cast<ssize_t>(sizeof(raw))) {
    return false;
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
