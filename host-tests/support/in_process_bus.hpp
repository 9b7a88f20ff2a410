// A device run in-process on a virtual clock, as a TranscriptBus.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "costa/port/memory/recording_can.hpp"
#include "device_target.hpp"
#include "transcript_player.hpp"

namespace costa::test {

/// Creates the device by its costa-slave name and powers it on at virtual time 0. Every call
/// into the device runs inside a NoAllocationScope.
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
  Microseconds now() const { return now_; }

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

  port::RecordingCan can_;
  std::unique_ptr<host::DeviceTarget> target_;
  Microseconds now_ = 0;
  Microseconds nextDeadline_ = 0;
  size_t cursor_ = 0;
};

}  // namespace costa::test
