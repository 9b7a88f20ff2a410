#include "simulated_channel.hpp"

namespace costa::santeng {
namespace {

/// Units (1/10000 RPM) running for 1 ms, times counts per revolution, per count.
constexpr int64_t kUnitMillisecondsPerRevolution = 60000 * SimulatedChannel::kUnitsPerRpm;
/// Largest magnitude of a reported current (A x 10).
constexpr int64_t kLargestCurrent = 32767;

int64_t magnitude(int64_t x) {
  return x < 0 ? -x : x;
}

int64_t sign(int64_t x) {
  return x < 0 ? -1 : (x > 0 ? 1 : 0);
}

/// Moves `value` towards `target` by at most `step` (> 0).
int64_t approach(int64_t value, int64_t target, int64_t step) {
  if (value < target) {
    return value + step > target ? target : value + step;
  }
  return value - step < target ? target : value - step;
}

bool speedMode(ChannelMode mode) {
  return mode != ChannelMode::kCountPosition;
}

int16_t clamp16(int64_t x, int64_t limit) {
  return static_cast<int16_t>(x > limit ? limit : (x < -limit ? -limit : x));
}

}  // namespace

void SimulatedChannel::reset() noexcept {
  const bool stalled = stalled_;
  *this = SimulatedChannel{};
  setStalled(stalled);
}

void SimulatedChannel::run(const ChannelCommand& command, Microseconds elapsed) noexcept {
  bool changed = false;
  for (Microseconds left = elapsed; left >= 1000U; left -= 1000U) {
    if (atRest(command)) {
      changed = changed || change_ != 0;
      change_ = 0;  // nothing changes any more in this step: no acceleration either
      break;
    }
    // One millisecond left is one step either way; a run of one millisecond always steps, which
    // is what santeng_channel_test.cpp compares a cruise with.
    if (left >= 2000U && cruising(command)) {
      cruise(command, left / 1000U);
      changed = true;
      break;
    }
    stepMillisecond(command);
    changed = true;
  }
  if (changed) {
    measure();
  }
}

bool SimulatedChannel::cruising(const ChannelCommand& command) const noexcept {
  // A step would change neither the ramp nor the speed, and there is no acceleration left to
  // show. A count position move may arrive on its count in a step: it takes its steps.
  return command.powered && speedMode(command.mode) && change_ == 0 && maxRpm_ == command.maxRpm &&
         mode_ == command.mode && ramped_ == targetSpeed(command) &&
         actual_ == (stalled_ ? 0 : ramped_);
}

void SimulatedChannel::cruise(const ChannelCommand& command, uint32_t steps) noexcept {
  // Each step adds the same amount to a remainder that starts within one count's units, so the
  // partial sums move one way and cross zero at most once: the counts that the steps would
  // truncate one by one are those of the whole sum, truncated once. At most 1000 steps at once
  // keep the sums far from overflowing (|v| < 2^30 units, 4 x lines < 2^18).
  constexpr uint32_t kChunk = 1000;
  while (steps > 0U) {
    const uint32_t n = steps < kChunk ? steps : kChunk;
    count_ += travel(int64_t{n} * actual_, command.encoderLines);
    steps -= n;
  }
}

int64_t SimulatedChannel::travel(int64_t unitMilliseconds, uint16_t encoderLines) noexcept {
  countRemainder_ += unitMilliseconds * 4 * encoderLines;
  const int64_t counts = countRemainder_ / kUnitMillisecondsPerRevolution;
  countRemainder_ -= counts * kUnitMillisecondsPerRevolution;
  hallRemainder_ += unitMilliseconds * kHallCountsPerRevolution;
  const int64_t hallCounts = hallRemainder_ / kUnitMillisecondsPerRevolution;
  hallRemainder_ -= hallCounts * kUnitMillisecondsPerRevolution;
  hallCount_ += hallCounts;
  return counts;
}

int64_t SimulatedChannel::positionTarget(const ChannelCommand& command) const noexcept {
  const int64_t remaining = int64_t{command.targetCount} - count_;
  int64_t cruise = magnitude(command.positionSpeed);
  cruise = cruise < command.maxRpm ? cruise : command.maxRpm;
  if (remaining == 0 || cruise == 0 || ramped_ * sign(remaining) < 0) {
    return 0;  // there, standing still, or moving away: brake first
  }
  if (command.deceleration > 0) {
    const int64_t rpm = magnitude(ramped_) / kUnitsPerRpm;
    const int64_t stopping = rpm * rpm * command.encoderLines / (3 * int64_t{command.deceleration});
    if (stopping >= magnitude(remaining)) {
      return 0;
    }
  }
  return sign(remaining) * cruise * kUnitsPerRpm;
}

int64_t SimulatedChannel::targetSpeed(const ChannelCommand& command) const noexcept {
  if (!command.powered || command.stopping) {
    return 0;
  }
  if (speedMode(command.mode)) {
    return int64_t{command.motorCommand} * command.maxRpm * (kUnitsPerRpm / 1000);
  }
  return positionTarget(command);
}

bool SimulatedChannel::atRest(const ChannelCommand& command) const noexcept {
  return actual_ == 0 && ramped_ == 0 && targetSpeed(command) == 0 && maxRpm_ == command.maxRpm &&
         mode_ == command.mode;
}

void SimulatedChannel::stepMillisecond(const ChannelCommand& command) noexcept {
  maxRpm_ = command.maxRpm;
  mode_ = command.mode;
  const int64_t before = ramped_;
  if (!command.powered) {
    ramped_ = 0;
    actual_ = approach(actual_, 0, kCoastRate);
  } else {
    const int64_t target = targetSpeed(command);
    const bool speedingUp = magnitude(target) > magnitude(ramped_) && target * ramped_ >= 0;
    const int64_t rate = speedingUp ? command.acceleration : command.deceleration;
    ramped_ = rate <= 0 ? target : approach(ramped_, target, rate);
    actual_ = stalled_ ? 0 : ramped_;
  }
  change_ = magnitude(ramped_ - before);
  move(command);
}

void SimulatedChannel::move(const ChannelCommand& command) noexcept {
  const int64_t counts = travel(actual_, command.encoderLines);
  const int64_t remaining = int64_t{command.targetCount} - count_;
  const bool positioning = !speedMode(command.mode) && command.powered && !command.stopping;
  if (positioning && remaining != 0 && sign(counts) == sign(remaining) &&
      magnitude(counts) >= magnitude(remaining)) {
    count_ = command.targetCount;  // arrived: stop on the count
    ramped_ = 0;
    actual_ = 0;
    countRemainder_ = 0;
    return;
  }
  count_ += counts;
}

void SimulatedChannel::measure() noexcept {
  // 0x5002 is 1..65535; a 0 that reached the channel otherwise counts as 1 RPM.
  const int64_t unitsPerMille = int64_t{maxRpm_ == 0U ? 1U : maxRpm_} * (kUnitsPerRpm / 1000);
  ChannelReading out;
  out.speedRpm = static_cast<int32_t>(actual_ / kUnitsPerRpm);
  out.appliedPermille = clamp16(ramped_ / unitsPerMille, 1000);
  out.speedPermille = clamp16(actual_ / unitsPerMille, 1000);
  out.encoderCount = static_cast<int32_t>(static_cast<uint32_t>(count_));
  out.hallCount = static_cast<int32_t>(static_cast<uint32_t>(hallCount_));
  const bool blocked = stalled_ && ramped_ != 0;
  int64_t motor = magnitude(actual_) / (50 * kUnitsPerRpm) + change_ / 500;
  if (blocked) {
    motor = magnitude(out.appliedPermille) / 10;
  }
  out.motorAmpsTimes10 = clamp16(motor, kLargestCurrent);
  out.batteryAmpsTimes10 = clamp16(motor * magnitude(out.appliedPermille) / 1000, kLargestCurrent);
  if (blocked) {
    out.motorFlags = static_cast<uint8_t>(kMotorStalled |
                                          (mode_ != ChannelMode::kOpenLoopSpeed ? kLoopError : 0U));
  }
  reading_ = out;
}

}  // namespace costa::santeng
