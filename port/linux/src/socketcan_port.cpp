#include "costa/port/linux/socketcan_port.hpp"

#include <errno.h>
#include <fcntl.h>
#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include <system_error>

namespace costa::port {

SocketCanPort::~SocketCanPort() {
  close();
}

void SocketCanPort::close() noexcept {
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
}

bool SocketCanPort::open(const std::string& interfaceName, std::string* error) {
  close();
  if (interfaceName.empty() || interfaceName.size() >= IFNAMSIZ) {
    *error = "invalid CAN interface name '" + interfaceName + "'";
    return false;
  }
  const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) {
    const int code = errno;
    *error = "cannot open a SocketCAN socket: " + std::system_category().message(code);
    if (code == EAFNOSUPPORT) {
      *error += " (this kernel has no SocketCAN; see README: run inside the vcan VM)";
    }
    return false;
  }
  const unsigned int index = if_nametoindex(interfaceName.c_str());
  if (index == 0U) {
    *error = "no such CAN interface: " + interfaceName;
    ::close(fd);
    return false;
  }
  // The controller's state changes only: protocol and acknowledgement errors are the
  // controller's business (it retransmits) and would flood the loop on a broken bus.
  const can_err_mask_t errorMask = CAN_ERR_CRTL | CAN_ERR_BUSOFF | CAN_ERR_RESTARTED;
  setsockopt(fd, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &errorMask, sizeof(errorMask));
  sockaddr_can address{};
  address.can_family = AF_CAN;
  address.can_ifindex = static_cast<int>(index);
  // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): the socket API takes sockaddr*
  if (::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0) {
    const int code = errno;
    *error = "cannot bind to CAN interface " + interfaceName + ": " +
             std::system_category().message(code);
    ::close(fd);
    return false;
  }
  fd_ = fd;
  errorState_ = SocketCanErrorState{};
  return true;
}

bool SocketCanPort::tryTransmit(const CanFrame& frame) noexcept {
  can_frame raw{};
  raw.can_id =
      frame.extended ? ((frame.id & CAN_EFF_MASK) | CAN_EFF_FLAG) : (frame.id & CAN_SFF_MASK);
  if (frame.rtr) {
    raw.can_id |= CAN_RTR_FLAG;
  }
  raw.len = frame.dlc > 8U ? 8U : frame.dlc;
  memcpy(raw.data, frame.data, 8);
  const ssize_t written = ::write(fd_, &raw, sizeof(raw));
  if (written != static_cast<ssize_t>(sizeof(raw))) {
    ++counters_.refused;
    return false;
  }
  ++counters_.transmitted;
  return true;
}

SocketCanPort::Received SocketCanPort::receive(CanFrame* frame, SocketCanEvents* events) noexcept {
  can_frame raw{};
  const ssize_t got = ::read(fd_, &raw, sizeof(raw));
  if (got < 0) {
    return (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) ? Received::kNothing
                                                                       : Received::kFailed;
  }
  if (got != static_cast<ssize_t>(sizeof(raw))) {
    return Received::kNothing;  // not a classic CAN frame (CAN FD is not enabled)
  }
  if ((raw.can_id & CAN_ERR_FLAG) != 0U) {
    ++counters_.errorFrames;
    const SocketCanEvents reported = controllerEventsOf(raw, &errorState_);
    if (events != nullptr) {
      *events = reported;
    }
    return Received::kErrorFrame;
  }
  *frame = CanFrame{};
  frame->extended = (raw.can_id & CAN_EFF_FLAG) != 0U;
  frame->rtr = (raw.can_id & CAN_RTR_FLAG) != 0U;
  frame->id = raw.can_id & (frame->extended ? CAN_EFF_MASK : CAN_SFF_MASK);
  frame->dlc = raw.len > 8U ? 8U : raw.len;
  if (!frame->rtr) {
    memcpy(frame->data, raw.data, frame->dlc);
  }
  ++counters_.received;
  return Received::kFrame;
}

bool SocketCanPort::setBitRate(uint32_t bitsPerSecond) noexcept {
  if (bitsPerSecond == 0U) {
    return false;
  }
  bitRate_ = bitsPerSecond;
  return true;
}

}  // namespace costa::port
