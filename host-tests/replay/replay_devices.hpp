// The devices transcripts name (targets/devices.hpp), built as costa-slave builds them for
// `--node-id N DEVICE` without --storage (targets/linux/device_registry.cpp): the same
// composition, the same DeviceConfig, the device's own memory, the same simulation commands.
#pragma once

#include <stdint.h>

#include "costa/port/can_port.hpp"
#include "replay_device.hpp"

namespace costa::replay {

/// Builds the device named `device` with node-id `nodeId` on `can` in static storage sized for
/// the largest device: one device at a time, building one destroys the one before. Null for a
/// name the device list does not have.
ReplayDevice* buildDevice(const char* device, uint8_t nodeId, CanTransmitter& can) noexcept;

/// Destroys the device built last, if any.
void destroyDevice() noexcept;

}  // namespace costa::replay
