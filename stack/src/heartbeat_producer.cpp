#include "costa/heartbeat_producer.hpp"

#include "costa/cob_ids.hpp"
#include "costa/od/little_endian.hpp"

namespace costa {

void HeartbeatProducer::restartWith(Microseconds now, uint32_t periodMs) noexcept {
  period_ = millisecondsToMicroseconds(periodMs);
  if (period_ == 0U) {
    next_ = kNever;  // no heartbeat: nothing to schedule
    return;
  }
  next_ = at(now, period_);
  clock_.schedule(next_);
}

void HeartbeatProducer::process(Microseconds now, NmtState state) noexcept {
  if (!reached(now, next_)) {
    return;
  }
  send(state);
  next_ = at(next_, period_);
  if (!before(now, next_)) {  // late by more than a period: keep the rhythm from now on
    next_ = at(now, period_);
  }
}

void HeartbeatProducer::send(NmtState state) noexcept {
  const auto value = static_cast<uint8_t>(state);
  tx_.send(cob::kErrorControlBase + nodeId_, &value, 1);
}

AbortCode HeartbeatProducer::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                                   const uint8_t* data, size_t length) noexcept {
  const AbortCode written = dictionary.write(ref, data, length);
  if (written == AbortCode::kNone) {
    restartWith(clock_.now,
                static_cast<uint32_t>(loadLittleEndian(data, length)));  // the value just written
  }
  return written;
}

}  // namespace costa
