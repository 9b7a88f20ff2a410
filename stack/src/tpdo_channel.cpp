#include "costa/tpdo_channel.hpp"

#include "costa/node_clock.hpp"

namespace costa {

void TpdoChannel::configure(PdoContext& context) noexcept {
  const od::ObjectDictionary& dictionary = context.access.dictionary();
  const PdoCobId cob =
      decodePdoCobId(static_cast<uint32_t>(dictionary.readUnsigned(index_, 1, 0x80000000U)),
                     context.profile.cobIdPolarity);
  valid_ = cob.valid && !cob.extended;
  rtrAllowed_ = cob.rtrAllowed;
  canId_ = cob.canId;
  type_ = static_cast<uint8_t>(dictionary.readUnsigned(index_, 2, 255));
  inhibit_ = dictionary.readUnsigned(index_, 3, 0) * kHundredMicroseconds;
  eventTimer_ = millisecondsToMicroseconds(dictionary.readUnsigned(index_, 5, 0));
  syncStart_ = static_cast<uint8_t>(dictionary.readUnsigned(index_, 6, 0));
  uint32_t values[PdoMap::kMaxEntries] = {};
  const size_t count = readMappingValues(dictionary, context.staticMappings, index_, values);
  if (map_.resolve(dictionary, values, count, PdoDirection::kTransmit) != AbortCode::kNone) {
    map_.clear();
  }
  sampledValid_ = false;
}

void TpdoChannel::start(PdoContext& context, Microseconds now, bool initialEvent) noexcept {
  running_ = true;
  syncCount_ = 0;
  waitingForStart_ = syncStart_ != 0U;
  sampledValid_ = false;
  inhibitUntil_ = 0;
  event_ = false;
  eventDeadline_ = kNever;
  if (eventDriven()) {
    event_ = initialEvent;
    if (eventTimer_ != 0U) {
      eventDeadline_ = now + eventTimer_;
    }
    context.clock.schedule(nextDeadline());
  }
}

void TpdoChannel::stop() noexcept {
  running_ = false;
  event_ = false;
  eventDeadline_ = kNever;
}

void TpdoChannel::signalEvent(NodeClock& clock) noexcept {
  if (running_ && (type_ == 0U || eventDriven())) {
    event_ = true;
    clock.schedule(nextDeadline());
  }
}

void TpdoChannel::onSync(PdoContext& context, uint8_t counter, Microseconds now,
                         Microseconds expiry) noexcept {
  if (!running_ || !valid_) {
    return;
  }
  if (type_ == 0U) {
    if (context.profile.tpdoType0 == TpdoType0::kEverySync || event_) {
      event_ = false;
      sendCurrent(context, now, expiry);
    }
  } else if (type_ <= 240U) {
    if (waitingForStart_ && counter != 0U) {
      if (counter != syncStart_) {
        return;
      }
      waitingForStart_ = false;
      syncCount_ = 0;
      sendCurrent(context, now, expiry);
      return;
    }
    if (++syncCount_ >= type_) {
      syncCount_ = 0;
      sendCurrent(context, now, expiry);
    }
  } else if (type_ == 252U) {
    map_.pack(context.access.dictionary(), sampled_);
    sampledValid_ = true;
  }
}

void TpdoChannel::onRemoteRequest(PdoContext& context, Microseconds now) noexcept {
  if (!running_ || !valid_ || !rtrAllowed_) {
    return;
  }
  if (type_ == 252U) {
    if (!sampledValid_) {
      map_.pack(context.access.dictionary(), sampled_);
    }
    send(context, sampled_, now, kNever);
  } else if (type_ >= 253U ||
             (type_ <= 240U && context.profile.tpdoRtrTypes == TpdoRtrTypes::kAllTypes)) {
    sendCurrent(context, now, kNever);
  }
}

void TpdoChannel::process(PdoContext& context, Microseconds now) noexcept {
  if (!running_ || !valid_ || !eventDriven()) {
    return;
  }
  if (eventDeadline_ != kNever && now >= eventDeadline_) {
    event_ = true;
  }
  if (event_ && now >= inhibitUntil_) {
    event_ = false;
    sendCurrent(context, now, kNever);
  }
}

Microseconds TpdoChannel::nextDeadline() const noexcept {
  if (!running_ || !valid_ || !eventDriven()) {
    return kNever;
  }
  Microseconds next = eventDeadline_;
  if (event_) {
    next = earliest(next, inhibitUntil_);
  }
  return next;
}

void TpdoChannel::sendCurrent(PdoContext& context, Microseconds now, Microseconds expiry) noexcept {
  uint8_t data[8] = {};
  map_.pack(context.access.dictionary(), data);
  send(context, data, now, expiry);
}

void TpdoChannel::send(PdoContext& context, const uint8_t* data, Microseconds now,
                       Microseconds expiry) noexcept {
  CanFrame frame;
  frame.id = canId_;
  size_t bytes = map_.bytes();
  if (bytes > sizeof(frame.data)) {
    bytes = sizeof(frame.data);
  }
  frame.dlc = static_cast<uint8_t>(bytes);
  for (size_t i = 0; i < bytes; ++i) {
    frame.data[i] = data[i];
  }
  context.tx.send(frame, expiry);
  inhibitUntil_ = now + inhibit_;
  if (eventTimer_ != 0U && eventDriven()) {
    eventDeadline_ = now + eventTimer_;
    context.clock.schedule(eventDeadline_);
  }
}

}  // namespace costa
