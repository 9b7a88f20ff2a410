#include "costa/heartbeat_producer.hpp"

#include "costa/cob_ids.hpp"

namespace costa {

void HeartbeatProducer::restart(Microseconds now) noexcept {
  period_ = millisecondsToMicroseconds(dictionary_.readUnsigned(kIndex, 0, 0));
  next_ = period_ == 0U ? kNever : now + period_;
  clock_.schedule(next_);
}

void HeartbeatProducer::process(Microseconds now, NmtState state) noexcept {
  if (next_ == kNever || now < next_) {
    return;
  }
  CanFrame frame;
  frame.id = cob::kErrorControlBase + nodeId_;
  frame.dlc = 1;
  frame.data[0] = static_cast<uint8_t>(state);
  tx_.send(frame);
  next_ += period_;
  if (next_ <= now) {  // late by more than a period: keep the rhythm from now on
    next_ = now + period_;
  }
}

AbortCode HeartbeatProducer::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                                   const uint8_t* data, size_t length) noexcept {
  const AbortCode written = dictionary.write(ref, data, length);
  if (written == AbortCode::kNone) {
    restart(clock_.now);
  }
  return written;
}

}  // namespace costa
