// The fuzzer's CAN controller: records what the node transmits and notes frames it must not.
#pragma once

#include <string>

#include "costa/port/memory/recording_can.hpp"
#include "frame_rules.hpp"
#include "fuzzed_device.hpp"

namespace costa::fuzz {

/// The recording controller, which also notes the first frame handed to it while the node must
/// send nothing: during an LSS bit timing switch, or while bus-off.
class WatchingCan final : public port::RecordingCan {
 public:
  /// The device whose node is asked at every frame (null: none yet). Starts over: no frame
  /// recorded, none noted, frames accepted.
  void watch(FuzzedDevice* device) {
    device_ = device;
    problem_.clear();
    clear();
    setAccepting(true);
  }
  bool tryTransmit(const CanFrame& frame) noexcept override {
    if (device_ != nullptr && problem_.empty()) {
      const Node& node = device_->node();
      if (node.lss().transmissionSuspended()) {
        problem_ = "frame " + describeFrame(frame) + " sent during an LSS bit timing switch";
      } else if (node.busOff()) {
        problem_ = "frame " + describeFrame(frame) + " handed to a bus-off controller";
      }
    }
    return RecordingCan::tryTransmit(frame);
  }
  /// The first such frame, or "".
  const std::string& problem() const { return problem_; }

 private:
  FuzzedDevice* device_ = nullptr;
  std::string problem_;
};

}  // namespace costa::fuzz
