#include "costa/indicators.hpp"

#include "costa/cob_ids.hpp"

namespace costa {
namespace {

constexpr Microseconds kFlicker = 50000;
constexpr Microseconds kFlash = 200000;
constexpr Microseconds kPause = 1000000;

/// A pattern: its phases' lengths, on and off alternately, the first one on.
struct Pattern {
  const Microseconds* phases;
  uint8_t count;
};

constexpr Microseconds kFlickerPhases[] = {kFlicker, kFlicker};
constexpr Microseconds kBlinkPhases[] = {kFlash, kFlash};
constexpr Microseconds kSingleFlashPhases[] = {kFlash, kPause};
constexpr Microseconds kDoubleFlashPhases[] = {kFlash, kFlash, kFlash, kPause};
constexpr Microseconds kTripleFlashPhases[] = {kFlash, kFlash, kFlash, kFlash, kFlash, kPause};

/// The phases of a flashing state; none (count 0) for on and off.
Pattern patternOf(IndicatorState state) noexcept {
  switch (state) {
    case IndicatorState::kFlickering: return {kFlickerPhases, 2};
    case IndicatorState::kBlinking: return {kBlinkPhases, 2};
    case IndicatorState::kSingleFlash: return {kSingleFlashPhases, 2};
    case IndicatorState::kDoubleFlash: return {kDoubleFlashPhases, 4};
    case IndicatorState::kTripleFlash: return {kTripleFlashPhases, 6};
    case IndicatorState::kOff:
    case IndicatorState::kOn: break;
  }
  return {nullptr, 0};
}

/// 1.5 times the SYNC period (0x1006, µs), within the longest delay the clock takes.
Microseconds syncTimeout(uint32_t period) noexcept {
  // period + half < kLongestDelay in 32 bits: half is at most kLongestDelay.
  const uint32_t half = period / 2U;
  return period < kLongestDelay - half ? period + half : kLongestDelay;
}

}  // namespace

Indicators::Indicators(Node& node, IndicatorOutputs& outputs) noexcept
    : node_(node), outputs_(outputs), attached_(node.addListener(*this)) {}

IndicatorState Indicators::runState() const noexcept {
  if (node_.lss().configurationState()) {
    return IndicatorState::kFlickering;
  }
  switch (node_.state()) {
    case NmtState::kPreOperational: return IndicatorState::kBlinking;
    case NmtState::kOperational: return IndicatorState::kOn;
    case NmtState::kStopped: return IndicatorState::kSingleFlash;
    case NmtState::kInitialising: break;
  }
  return IndicatorState::kOff;
}

IndicatorState Indicators::errorState(Microseconds now) noexcept {
  if (node_.busOff()) {
    return IndicatorState::kOn;
  }
  if (node_.lss().configurationState()) {
    return IndicatorState::kFlickering;
  }
  if (syncDeadline_ != kNever && reached(now, syncDeadline_)) {
    syncError_ = true;  // until the next SYNC or reset communication
    syncDeadline_ = kNever;
  }
  if (syncError_) {
    return IndicatorState::kTripleFlash;
  }
  if (heartbeatTimeouts_ != 0U || lifeGuardingExpired_) {
    return IndicatorState::kDoubleFlash;
  }
  if (node_.errorControl().errorPassive()) {
    return IndicatorState::kSingleFlash;
  }
  return IndicatorState::kOff;
}

bool Indicators::update(Led& led, IndicatorState state, bool inverted, Microseconds now) noexcept {
  const bool wasOn = led.level;
  const Pattern pattern = patternOf(state);
  if (state != led.state || inverted != led.inverted) {
    led.state = state;
    led.inverted = inverted;
    led.phase = 0;
    led.phaseEnd = pattern.count != 0U ? at(now, pattern.phases[0]) : kNever;
  }
  while (pattern.count != 0U && reached(now, led.phaseEnd)) {
    // led.phase is below pattern.count: it restarts at 0 with every change of pattern.
    led.phase = led.phase + 1U < pattern.count ? static_cast<uint8_t>(led.phase + 1U) : uint8_t{0};
    led.phaseEnd = at(led.phaseEnd, pattern.phases[led.phase]);
  }
  // Even phases are on; an inverted LED is off where the other is on.
  const bool on =
      pattern.count != 0U ? ((led.phase % 2U) == 0U) != inverted : state == IndicatorState::kOn;
  led.level = on;
  return on != wasOn;
}

Microseconds Indicators::process(Microseconds now) noexcept {
  const IndicatorState error = errorState(now);
  if (update(run_, runState(), false, now)) {
    outputs_.setRun(run_.level);
  }
  // In LSS configuration state ERROR flickers opposite to RUN.
  if (update(error_, error, error == IndicatorState::kFlickering, now)) {
    outputs_.setError(error_.level);
  }
  Microseconds next = earliest(run_.phaseEnd, error_.phaseEnd);
  return earliest(next, syncDeadline_);
}

void Indicators::onSync(uint8_t counter) noexcept {
  (void)counter;
  const od::ObjectDictionary& dictionary = node_.dictionary();
  const auto cob = dictionary.readUnsigned32(0x1005, 0, 0);
  const auto period = dictionary.readUnsigned32(0x1006, 0, 0);
  const bool producer = (cob & 0x40000000U) != 0U;
  syncError_ = false;
  syncDeadline_ = producer || period == 0U ? kNever : at(node_.now(), syncTimeout(period));
}

void Indicators::onResetCommunication() noexcept {
  syncDeadline_ = kNever;
  syncError_ = false;
  heartbeatTimeouts_ = 0;
  lifeGuardingExpired_ = false;
}

void Indicators::onHeartbeatTimeout(uint8_t nodeId) noexcept {
  (void)nodeId;
  ++heartbeatTimeouts_;
}

void Indicators::onHeartbeatResumed(uint8_t nodeId) noexcept {
  (void)nodeId;
  if (heartbeatTimeouts_ != 0U) {
    --heartbeatTimeouts_;
  }
}

void Indicators::onHeartbeatWithdrawn(uint8_t nodeId) noexcept {
  onHeartbeatResumed(nodeId);  // the entry's error ends as if its producer had returned
}

}  // namespace costa
