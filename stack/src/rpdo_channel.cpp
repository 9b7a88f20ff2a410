#include "costa/rpdo_channel.hpp"

#include "costa/emcy_producer.hpp"
#include "costa/node_clock.hpp"
#include "costa/node_events.hpp"
#include "costa/od/bytes.hpp"
#include "costa/tpdo_channel.hpp"

namespace costa {

AbortCode RpdoChannel::configure(PdoContext& context) noexcept {
  (void)readCommunication(context);
  stop();
  // The EMCY conditions the old parameters raised no longer apply.
  static constexpr Condition kConditions[] = {kTimedOut, kTooShort, kTooLong};
  for (const Condition condition : kConditions) {
    setCondition(context, condition, false);
  }
  return resolveMapping(context);
}

void RpdoChannel::updateQuietDlc() noexcept {
  if constexpr (kExpandFastPaths) {  // (built for size, onFrame() does not look at it)
    // cppcheck-suppress knownConditionTrueFalse ; false in a build without quirk profiles
    quietDlc_ = raised(kTooShort) || raised(kTooLong) || answered()
                    ? 0xFFU
                    : static_cast<uint8_t>(map_.bytes());
  }
}

void RpdoChannel::takeBackAnswer(PdoContext& context) const noexcept {
  context.tpdos[answer_ - 1U].withdrawEvent();
}

void RpdoChannel::setCondition(PdoContext& context, Condition condition, bool on) noexcept {
  // By condition bit: 1, 2, 4 -> 0x8210, 0x8220, 0x8250 (0x8200 + 0x10 x 1, 2, 5).
  static_assert(kTooShort == 1U && kTooLong == 2U && kTimedOut == 4U &&
                    kEmcyLengthShort == 0x8210U && kEmcyLengthLong == 0x8220U &&
                    kEmcyTimeout == 0x8250U,
                "codes by bit");
  const unsigned bit = condition;
  const auto code = static_cast<uint16_t>(0x8200U + ((bit + (bit >> 2U)) << 4U));
  if (on) {
    raised_ |= condition;
    context.emcy.raise(code, source(), kErrorCommunication);
  } else if (raised(condition)) {
    raised_ &= static_cast<uint8_t>(~condition);
    context.emcy.clear(code, source());
  }
}

bool RpdoChannel::checkLength(PdoContext& context, uint8_t dlc) noexcept {
  const size_t bytes = map_.bytes();
  if (dlc < bytes) {
    setCondition(context, kTooShort, true);
    updateQuietDlc();
    return false;
  }
  if (raised_ != 0U || dlc > bytes) {  // (the usual frame raises and clears nothing: no call)
    setCondition(context, kTooShort, false);
    setCondition(context, kTooLong, dlc > bytes);
  }
  updateQuietDlc();
  // cppcheck-suppress knownConditionTrueFalse ; false in a build without quirk profiles
  if (answered()) {
    // Taken: answered (withdrawn if an entry refuses).
    answerSignalled_ = context.tpdos[answer_ - 1U].signalEvent(context.clock);
  }
  return true;
}

void RpdoChannel::restartDeadline(PdoContext& context, Microseconds now) noexcept {
  deadline_ = at(now, millisecondsToMicroseconds(eventTimerMs_));
  context.clock.schedule(deadline_);
  setCondition(context, kTimedOut, false);
}

bool RpdoChannel::applyChecked(PdoContext& context, const uint8_t* data) noexcept {
  // (built for size, a plain mapping comes here too: nothing of it needs a check)
  if ((kExpandFastPaths || !map_.plain()) && map_.check(context.access, data) != AbortCode::kNone) {
    return false;
  }
  notifyWriting(context);
  if (map_.write(context.access, data) != AbortCode::kNone) {
    return false;
  }
  notifyReceived(context);
  return true;
}

void RpdoChannel::process(PdoContext& context, Microseconds now) noexcept {
  if (reached(now, deadline_)) {  // (never while kTimedOut: deadline_ is kNever then)
    deadline_ = kNever;
    setCondition(context, kTimedOut, true);
    const uint16_t index = index_;
    context.listeners.notify([index](NodeEvents& listener) { listener.onRpdoTimeout(index); });
  }
}

}  // namespace costa
