// A device run in-process on a virtual clock, as a TranscriptBus.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "costa/port/memory/recording_can.hpp"
#include "device_target.hpp"
#include "transcript_player.hpp"
#include "virtual_clock.hpp"

namespace costa::test {

/// Creates the device by its costa-slave name and powers it on at virtual time powerOnTime()
/// (0, or COSTA_TEST_CLOCK_START from the environment, so that a whole test run can cross the
/// wrap of the 32-bit microsecond clock). Every call into the device runs inside a
/// NoAllocationScope.
class InProcessBus : public TranscriptBus {
 public:
  InProcessBus(const std::string& device, int nodeId,
               const host::TargetOptions& extra = host::TargetOptions{});
  /// A device made by `factory` on this bus's CAN transmitter.
  using Factory = std::function<std::unique_ptr<host::DeviceTarget>(CanTransmitter&)>;
  explicit InProcessBus(const Factory& factory);

  void send(const CanFrame& frame) override;
  bool receive(CanFrame* frame, int timeoutMs) override;
  void wait(uint64_t milliseconds) override;
  bool checksTiming() const override { return true; }
  std::string simulate(const std::string& command) override { return target_->control(command); }

  /// Advances virtual time by `microseconds`, running every deadline on the way.
  void advance(Microseconds microseconds);
  Microseconds now() const { return clock_.now(); }
  /// Virtual time elapsed since power-on.
  Microseconds elapsed() const { return clock_.now() - powerOnTime(); }
  /// The virtual time of power-on: COSTA_TEST_CLOCK_START (a number of microseconds) when the
  /// environment has it, else 0.
  static Microseconds powerOnTime();

  host::DeviceTarget& target() { return *target_; }
  Node& node() { return target_->node(); }
  port::RecordingCan& can() { return can_; }
  /// Frames sent and not yet received by the transcript.
  size_t unread() const { return can_.count() - cursor_; }

 private:
  void powerOn();
  /// Calls process() now, again while it asks for an immediate call. False (and a test
  /// failure) when it never stops asking, or asks for a time in the past.
  bool runProcess();
  bool checked(replay::VirtualClock::Outcome outcome);

  port::RecordingCan can_;
  std::unique_ptr<host::DeviceTarget> target_;
  replay::VirtualClock clock_{powerOnTime()};
  size_t cursor_ = 0;
};

}  // namespace costa::test
