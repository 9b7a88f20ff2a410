#include "costa/tpdo_channel.hpp"

#include "costa/node_clock.hpp"
#include "costa/od/bytes.hpp"

namespace costa {

AbortCode TpdoChannel::configure(PdoContext& context) noexcept {
  rtrAllowed_ = readCommunication(context);
  const od::ObjectDictionary& dictionary = context.access.dictionary();
  inhibit_ = static_cast<uint16_t>(dictionary.readUnsigned32(index_, 3, 0));
  syncStart_ = static_cast<uint8_t>(dictionary.readUnsigned32(index_, 6, 0));
  sampledValid_ = false;
  updateSyncPeriod();
  return resolveMapping(context);
}

void TpdoChannel::begin(PdoContext& context, Microseconds now, bool event,
                        Microseconds inhibitEnd) noexcept {
  running_ = true;
  syncCount_ = 0;
  waitingForStart_ = syncStart_ != 0U;
  updateSyncPeriod();
  sampledValid_ = false;
  event_ = event && takesEvents();
  inhibitUntil_ = kNever;
  eventDeadline_ = kNever;
  if (eventDriven()) {
    inhibitUntil_ = inhibitEnd;
    if (eventTimerMs_ != 0U) {
      eventDeadline_ = at(now, millisecondsToMicroseconds(eventTimerMs_));
    }
    context.clock.schedule(nextDeadline(now));
  }
}

void TpdoChannel::stop() noexcept {
  running_ = false;
  updateSyncPeriod();
  event_ = false;
  eventDeadline_ = kNever;
}

void TpdoChannel::onRemoteRequest(PdoContext& context, Microseconds now) noexcept {
  if (!rtrAllowed_) {  // (running and valid: PdoEngine::remoteRequest() asked)
    return;
  }
  if (type_ == 252U) {
    // The values sampled at the last SYNC, or, before there is one, the current values.
    send(context, sampledValid_ ? sampled_ : nullptr, now, kNever);
  } else if (eventDriven() && inhibitUntil_ != kNever && !reached(now, inhibitUntil_)) {
    // CiA 301: the inhibit time is the least interval between transmissions of an event-driven
    // TPDO, answers included: within it the answer waits as an event does (process()).
    (void)signalEvent(context.clock);
  } else if (type_ >= 253U ||
             (type_ <= 240U && context.profile.tpdoRtrTypes == TpdoRtrTypes::kAllTypes)) {
    sendCurrent(context, now, kNever);
  }
}

void TpdoChannel::process(PdoContext& context, Microseconds now) noexcept {
  if (!valid_ || !eventDriven()) {  // (running: PdoEngine::process() asks only then)
    return;
  }
  if (reached(now, eventDeadline_)) {
    event_ = true;            // sent now, or when the inhibit time ends
    eventDeadline_ = kNever;  // the timer restarts when the PDO is sent
  }
  if (reached(now, inhibitUntil_)) {
    inhibitUntil_ = kNever;  // the inhibit time is over
  }
  if (event_ && inhibitUntil_ == kNever) {
    event_ = false;
    sendCurrent(context, now, kNever);
  }
}

Microseconds TpdoChannel::nextDeadline(Microseconds now) const noexcept {
  if (!valid_ || !eventDriven()) {  // (running: every caller asks only then)
    return kNever;
  }
  // The end of an inhibit time is a deadline too: it expires there.
  const Microseconds next = earliest(eventDeadline_, inhibitUntil_);
  return event_ && inhibitUntil_ == kNever ? atOnce(now) : next;
}

void TpdoChannel::send(PdoContext& context, const uint8_t* sample, Microseconds now,
                       Microseconds expiry) noexcept {
  CanFrame frame;
  frame.id = canId_;
  frame.dlc = static_cast<uint8_t>(map_.bytes());
  if (sample != nullptr) {
    copyBytes(frame.data, sample, frame.dlc);
  } else {
    map_.pack(context.access, frame.data);
  }
  context.tx.send(frame, expiry);
  if (!eventDriven()) {
    return;  // the inhibit time and the event timer are those of event-driven transmission
  }
  inhibitUntil_ = inhibit_ == 0U ? kNever : at(now, inhibit_ * kHundredMicroseconds);
  context.clock.schedule(inhibitUntil_);
  if (eventTimerMs_ != 0U) {
    eventDeadline_ = at(now, millisecondsToMicroseconds(eventTimerMs_));
    context.clock.schedule(eventDeadline_);
  }
}

}  // namespace costa
