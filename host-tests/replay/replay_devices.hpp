// The devices transcripts name, built as costa-slave builds them for `--node-id N DEVICE`
// without --storage (targets/linux/device_registry.cpp): the same settings, the same storage
// (the device's own RAM "EEPROM"), the same simulation commands.
#pragma once

#include <stdint.h>

#include "costa/port/can_port.hpp"
#include "replay_device.hpp"
#include "replay_script.hpp"

namespace costa::replay {

/// Builds `device` with node-id `nodeId` on `can` in static storage sized for the largest
/// device: one device at a time, building one destroys the one before.
ReplayDevice& buildDevice(DeviceKind device, uint8_t nodeId, CanTransmitter& can) noexcept;

/// Destroys the device built last, if any.
void destroyDevice() noexcept;

}  // namespace costa::replay
