#include "costa/srdo_channel.hpp"

namespace costa {

void SrdoChannel::start(const SrdoConfiguration& configuration, Microseconds now) noexcept {
  configuration_ = configuration;
  running_ = true;
  validationEnd_ = kNever;
  next_ = configuration.direction == srdo::kTransmit
              ? now
              : at(now, millisecondsToMicroseconds(configuration.cycleMs));
}

bool SrdoChannel::transmitDue(Microseconds now) noexcept {
  if (!running_ || configuration_.direction != srdo::kTransmit || !reached(now, next_)) {
    return false;
  }
  const Microseconds cycle = millisecondsToMicroseconds(configuration_.cycleMs);
  // The next pair one SCT after this one was due; late by a cycle or more: from now.
  next_ = at(now - next_ >= cycle ? now : next_, cycle);
  return true;
}

SrdoFailure SrdoChannel::checkDeadlines(Microseconds now) const noexcept {
  if (!running_ || configuration_.direction != srdo::kReceive) {
    return SrdoFailure::kNone;
  }
  if (validationEnd_ != kNever && reached(now, validationEnd_)) {
    return SrdoFailure::kValidationTime;
  }
  return reached(now, next_) ? SrdoFailure::kCycleTime : SrdoFailure::kNone;
}

SrdoFailure SrdoChannel::onFrame(const CanFrame& frame, bool inverted, Microseconds now,
                                 bool* complete) noexcept {
  *complete = false;
  const SrdoFailure late = checkDeadlines(now);
  if (late != SrdoFailure::kNone) {
    return late;
  }
  if (frame.rtr || frame.dlc != configuration_.length) {
    return SrdoFailure::kLength;
  }
  const bool awaitingInverted = validationEnd_ != kNever;
  if (inverted != awaitingInverted) {
    return SrdoFailure::kSequence;
  }
  if (!inverted) {
    for (uint8_t i = 0; i < frame.dlc; ++i) {
      normal_[i] = frame.data[i];
    }
    validationEnd_ = at(now, millisecondsToMicroseconds(configuration_.validationMs));
    return SrdoFailure::kNone;
  }
  for (uint8_t i = 0; i < frame.dlc; ++i) {
    if (static_cast<uint8_t>(~normal_[i]) != frame.data[i]) {
      return SrdoFailure::kNotInverted;
    }
  }
  validationEnd_ = kNever;
  next_ = at(now, millisecondsToMicroseconds(configuration_.cycleMs));
  *complete = true;
  return SrdoFailure::kNone;
}

Microseconds SrdoChannel::nextDeadline() const noexcept {
  return running_ ? earliest(next_, validationEnd_) : kNever;
}

}  // namespace costa
