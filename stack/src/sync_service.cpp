#include "costa/sync_service.hpp"

#include "costa/cob_ids.hpp"
#include "costa/emcy_producer.hpp"
#include "costa/frame_router.hpp"
#include "costa/od/little_endian.hpp"

namespace costa {

void SyncService::configure(Microseconds now) noexcept {
  readParameters();
  counter_ = 1;
  clearLengthError();  // it belonged to the parameters before
  if (producing()) {
    timer_.start(now, period_);
    clock_.schedule(timer_.next());
  } else {
    timer_.stop();
  }
  routes_.invalidate();
}

void SyncService::readParameters() noexcept {
  const auto cob = dictionary_.readUnsigned32(kCobIdIndex, 0, 0x080);
  canId_ = cob & 0x7FFU;
  producer_ = (cob & 0x40000000U) != 0U;
  period_ = dictionary_.readUnsigned32(kPeriodIndex, 0, 0);
  // A window longer than the stack's longest delay (35 min) acts as that long.
  const auto window = dictionary_.readUnsigned32(kWindowIndex, 0, 0);
  window_ = window < kLongestDelay ? window : kLongestDelay;
  overflow_ = static_cast<uint8_t>(dictionary_.readUnsigned32(kOverflowIndex, 0, 0));
}

void SyncService::clearLengthError() noexcept {
  if (lengthError_) {
    lengthError_ = false;
    emcy_.clear(kEmcyUnexpectedLength, 0);
  }
}

bool SyncService::onFrame(const CanFrame& frame, Microseconds now, SyncEvent* event) noexcept {
  const uint8_t expected = overflow_ >= 2U ? 1U : 0U;
  event->counter = expected != 0U ? frame.data[0] : 0U;  // (not used when the length is wrong)
  if (frame.dlc != expected) {
    lengthError_ = true;
    emcy_.raise(kEmcyUnexpectedLength, 0, kErrorCommunication);
    return false;
  }
  clearLengthError();
  return report(now, event);
}

bool SyncService::process(Microseconds now, bool allowed, SyncEvent* event) noexcept {
  if (!producer_ || !timer_.fired(now)) {
    return false;
  }
  // The next SYNC one period after this one was due; late by a period or more: from now.
  const Microseconds due = timer_.due();
  timer_.start(now - due >= period_ ? now : due, period_);
  if (!allowed) {
    return false;
  }
  uint8_t length = 0;
  event->counter = 0;
  if (overflow_ >= 2U) {
    length = 1;
    event->counter = counter_;
    counter_ = counter_ >= overflow_ ? 1U : static_cast<uint8_t>(counter_ + 1U);
  }
  tx_.send(canId_, &event->counter, length);  // the counter is the SYNC's one byte
  return report(now, event);
}

AbortCode SyncService::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                             const uint8_t* data, size_t length) noexcept {
  // The index as its distance from 0x1005: compared with short constants.
  const unsigned index = ref.index() - kCobIdIndex;
  if (index == 0U && length == 4U) {
    // SYNC has no valid bit: a restricted CAN-ID is refused even to consume (0x601 is SDO); a
    // producer stops producing before it changes the CAN-ID.
    const auto value = static_cast<uint32_t>(loadLittleEndian(data, length));
    const bool producing = producer_ && (value & 0x40000000U) != 0U;
    if (!cob::acceptableCobId(value, true, producing, canId_)) {
      return AbortCode::kInvalidValue;
    }
  }
  if (index == kOverflowIndex - kCobIdIndex && length == 1U) {
    if (data[0] == 1U || data[0] > 240U) {
      return AbortCode::kInvalidValue;
    }
    if (period_ != 0U) {
      return AbortCode::kCannotStoreState;  // CiA 301: only while the cycle period is 0
    }
  }
  // A running cycle keeps its counter; one that starts, starts at 1. (The counter of a node
  // that does not produce is never sent: production starts with configure(), which sets 1.)
  const uint8_t counter = producing() ? counter_ : uint8_t{1};
  const AbortCode written = dictionary.write(ref, data, length);
  if (written != AbortCode::kNone) {
    return written;
  }
  if (index == kWindowIndex - kCobIdIndex) {
    readParameters();  // the window alone: the cycle and its counter go on
    return written;
  }
  configure(clock_.now);  // the period from the write
  counter_ = counter;
  return written;
}

}  // namespace costa
