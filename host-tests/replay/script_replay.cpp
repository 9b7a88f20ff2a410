#include "script_replay.hpp"

#include "replay_devices.hpp"
#include "script_player.hpp"
#include "virtual_bus.hpp"

namespace costa::replay {

bool replayScript(const Script& script, FrameRecorder& recorder, Text& verdict) noexcept {
  recorder.reset();
  ReplayDevice* device = buildDevice(script.device, script.nodeId, recorder);
  if (device == nullptr) {
    verdict.clear();
    verdict.append(script.name).append(": device '").append(script.device);
    verdict.append("' is not in the device list");
    return false;
  }
  VirtualBus bus(*device, recorder);
  const bool passed = playScript(script, bus, verdict);
  destroyDevice();
  return passed;
}

}  // namespace costa::replay
