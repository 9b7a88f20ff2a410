#include "dummy_can.hpp"

namespace costa::firmware {

bool DummyCan::tryTransmit(const CanFrame& frame) noexcept {
  mailbox_.tx = frame;
  mailbox_.txCount = mailbox_.txCount + 1U;
  return true;
}

bool DummyCan::receive(CanFrame* frame) noexcept {
  if (mailbox_.rxCount == seen_) {
    return false;
  }
  seen_ = mailbox_.rxCount;
  *frame = mailbox_.rx;
  return true;
}

}  // namespace costa::firmware
