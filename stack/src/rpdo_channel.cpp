#include "costa/rpdo_channel.hpp"

#include "costa/emcy_producer.hpp"
#include "costa/node_clock.hpp"
#include "costa/node_events.hpp"

namespace costa {

void RpdoChannel::configure(PdoContext& context) noexcept {
  const od::ObjectDictionary& dictionary = context.access.dictionary();
  const PdoCobId cob =
      decodePdoCobId(static_cast<uint32_t>(dictionary.readUnsigned(index_, 1, 0x80000000U)),
                     context.profile.cobIdPolarity);
  valid_ = cob.valid && !cob.extended;
  canId_ = cob.canId;
  type_ = static_cast<uint8_t>(dictionary.readUnsigned(index_, 2, 255));
  eventTimer_ = millisecondsToMicroseconds(dictionary.readUnsigned(index_, 5, 0));
  uint32_t values[PdoMap::kMaxEntries] = {};
  const size_t count = readMappingValues(dictionary, context.staticMappings, index_, values);
  if (map_.resolve(dictionary, values, count, PdoDirection::kReceive) != AbortCode::kNone) {
    map_.clear();
  }
  stop();
}

void RpdoChannel::stop() noexcept {
  holding_ = false;
  deadline_ = kNever;
  timedOut_ = false;
}

void RpdoChannel::onFrame(PdoContext& context, const CanFrame& frame, Microseconds now) noexcept {
  if (frame.dlc < map_.bytes()) {
    context.emcy.raise(kEmcyLengthShort, source(), kErrorCommunication);
    return;
  }
  context.emcy.clear(kEmcyLengthShort, source());
  if (frame.dlc > map_.bytes()) {
    context.emcy.raise(kEmcyLengthLong, source(), kErrorCommunication);
  } else {
    context.emcy.clear(kEmcyLengthLong, source());
  }
  if (eventTimer_ != 0U) {
    deadline_ = now + eventTimer_;
    context.clock.schedule(deadline_);
    if (timedOut_) {
      timedOut_ = false;
      context.emcy.clear(kEmcyTimeout, source());
    }
  }
  if (type_ <= 240U) {
    for (size_t i = 0; i < map_.bytes() && i < sizeof(held_); ++i) {
      held_[i] = frame.data[i];
    }
    holding_ = true;
  } else if (type_ >= 254U) {
    apply(context, frame.data);
  }
}

void RpdoChannel::onSync(PdoContext& context) noexcept {
  if (holding_) {
    holding_ = false;
    apply(context, held_);
  }
}

void RpdoChannel::apply(PdoContext& context, const uint8_t* data) noexcept {
  map_.unpack(context.access, data);
  const uint16_t index = index_;
  context.listeners.notify([index](NodeEvents& listener) { listener.onRpdoReceived(index); });
}

void RpdoChannel::process(PdoContext& context, Microseconds now) noexcept {
  if (deadline_ != kNever && !timedOut_ && now >= deadline_) {
    timedOut_ = true;
    deadline_ = kNever;
    context.emcy.raise(kEmcyTimeout, source(), kErrorCommunication);
    const uint16_t index = index_;
    context.listeners.notify([index](NodeEvents& listener) { listener.onRpdoTimeout(index); });
  }
}

Microseconds RpdoChannel::nextDeadline() const noexcept {
  return timedOut_ ? kNever : deadline_;
}

}  // namespace costa
