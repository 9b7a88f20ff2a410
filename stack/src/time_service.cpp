#include "costa/time_service.hpp"

#include "costa/cob_ids.hpp"
#include "costa/frame_router.hpp"
#include "costa/od/little_endian.hpp"
#include "costa/shift_arithmetic.hpp"

namespace costa {
namespace {

/// The clock of day is folded forward this often, far inside the 71.6 min of the µs clock.
constexpr uint32_t kRebasePeriod = 600000000;  // 10 min
constexpr uint32_t kMillisecondMask = 0x0FFFFFFF;

/// `time` `elapsed` milliseconds later, `elapsed` below a day (at most 4,294,967: the µs clock's
/// range in ms). time.milliseconds is below a day too, so the sum is below two days.
TimeOfDay later(const TimeOfDay& time, uint32_t elapsed) noexcept {
  constexpr uint32_t kDay = TimeOfDay::kMillisecondsPerDay;
  static_assert(UINT32_MAX / 1000U < kDay, "elapsed is below a day");
  TimeOfDay result;
  result.milliseconds = time.milliseconds + elapsed;
  result.days = time.days;
  if (result.milliseconds >= kDay) {
    result.milliseconds -= kDay;
    ++result.days;
  }
  return result;
}

}  // namespace

void TimeService::configure() noexcept {
  // Without the object the default 0x100 has neither bit: no TIME.
  const auto cob = dictionary_.readUnsigned32(kCobIdIndex, 0, 0x100);
  canId_ = static_cast<uint16_t>(cob & 0x7FFU);
  consumer_ = (cob & kConsume) != 0U;
  producer_ = (cob & kProduce) != 0U;
  routes_.invalidate();
}

bool TimeService::onFrame(const CanFrame& frame, Microseconds now) noexcept {
  const uint32_t milliseconds = loadU32(frame.data) & kMillisecondMask;
  if (frame.rtr || frame.dlc != kLength || milliseconds >= TimeOfDay::kMillisecondsPerDay) {
    ++framesIgnored_;
    return false;
  }
  TimeOfDay time;
  time.milliseconds = milliseconds;
  time.days = loadU16(frame.data + 4);
  return setTimeOfDay(time, now);
}

bool TimeService::setTimeOfDay(const TimeOfDay& time, Microseconds now) noexcept {
  if (time.milliseconds >= TimeOfDay::kMillisecondsPerDay) {
    return false;
  }
  base_ = time;
  baseAt_ = now;
  schedule(&rebaseAt_, at(now, kRebasePeriod));
  if (period_ != 0U && nextTime_ == kNever) {
    schedule(&nextTime_, at(now, period_));
  }
  return true;
}

void TimeService::advanceTo(Microseconds now) noexcept {
  const Quotient elapsed = divide(now - baseAt_, 1000U);  // whole ms, and the µs left over
  baseAt_ = now - elapsed.remainder;
  base_ = later(base_, elapsed.quotient);
}

bool TimeService::timeOfDay(Microseconds now, TimeOfDay* out) const noexcept {
  if (rebaseAt_ == kNever) {
    return false;
  }
  *out = later(base_, divide(now - baseAt_, 1000U).quotient);
  return true;
}

void TimeService::setProducerPeriod(Microseconds period, Microseconds now) noexcept {
  period_ = period < kLongestDelay ? period : kLongestDelay;
  nextTime_ = kNever;
  if (period == 0U || rebaseAt_ == kNever) {
    return;  // stopped, or nothing to send until the clock of day is set
  }
  schedule(&nextTime_, at(now, period_));
}

void TimeService::process(Microseconds now, bool allowed) noexcept {
  if (rebaseAt_ != kNever && reached(now, rebaseAt_)) {
    advanceTo(now);
    schedule(&rebaseAt_, at(now, kRebasePeriod));
  }
  if (nextTime_ == kNever || !reached(now, nextTime_)) {
    return;
  }
  // The next TIME one period after this one was due; late by a period or more: from now.
  const Microseconds due = nextTime_;
  schedule(&nextTime_, at(now - due >= period_ ? now : due, period_));
  if (!allowed || !producer_) {
    return;
  }
  advanceTo(now);
  uint8_t data[kLength];
  encode(base_, data);
  tx_.send(canId_, data, kLength);
}

void TimeService::encode(const TimeOfDay& time, uint8_t* bytes) noexcept {
  storeU32(bytes, time.milliseconds & kMillisecondMask);
  storeU16(bytes + 4, time.days);
}

AbortCode TimeService::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                             const uint8_t* data, size_t length) noexcept {
  if (ref.index() == kCobIdIndex && length == 4U) {
    // TIME has no valid bit: a restricted CAN-ID is always refused; bits 31 and 30 (consumer,
    // producer) are cleared before the CAN-ID changes.
    const uint32_t value = loadU32(data);
    if (!cob::acceptableCobId(value, true, consumer_ || producer_, canId_)) {
      return AbortCode::kInvalidValue;
    }
  }
  const AbortCode written = dictionary.write(ref, data, length);
  if (written == AbortCode::kNone) {
    configure();
  }
  return written;
}

}  // namespace costa
