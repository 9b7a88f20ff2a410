#include "replay_devices.hpp"

#include <new>

#include "devices.hpp"

namespace costa::replay {
namespace {

constexpr size_t larger(size_t a, size_t b) {
  return a > b ? a : b;
}

/// The size and alignment of the largest ReplayedComposition of the list.
constexpr size_t kSlotBytes = [] {
  size_t bytes = 0;
  devices::forEachDevice([&bytes](auto device) {
    using Composition = typename decltype(device)::Composition;
    bytes = larger(bytes, sizeof(ReplayedComposition<Composition>));
  });
  return bytes;
}();
constexpr size_t kSlotAlignment = [] {
  size_t alignment = 1;
  devices::forEachDevice([&alignment](auto device) {
    using Composition = typename decltype(device)::Composition;
    alignment = larger(alignment, alignof(ReplayedComposition<Composition>));
  });
  return alignment;
}();

alignas(kSlotAlignment) unsigned char slot[kSlotBytes];
void* built = nullptr;  ///< the device in `slot`
void (*destroyBuilt)(void*) noexcept = nullptr;

template <typename Device>
void destroy(void* device) noexcept {
  static_cast<Device*>(device)->~Device();
}

template <typename Device>
ReplayDevice* build(CanTransmitter& can, const DeviceConfig& config) noexcept {
  static_assert(sizeof(Device) <= kSlotBytes, "the slot holds every device");
  Device* device = ::new (static_cast<void*>(slot)) Device(can, config);
  built = device;
  destroyBuilt = &destroy<Device>;
  return device;
}

}  // namespace

ReplayDevice* buildDevice(const char* device, uint8_t nodeId, CanTransmitter& can) noexcept {
  destroyDevice();
  DeviceConfig config;  // no --storage: the device's own memory
  config.nodeId = nodeId;
  config.nodeIdGiven = true;  // --node-id N
  ReplayDevice* made = nullptr;
  devices::forEachDevice([&](auto listed) {
    using Composition = typename decltype(listed)::Composition;
    if (made == nullptr && devices::isNamed(listed.name, device)) {
      made = build<ReplayedComposition<Composition>>(can, config);
    }
  });
  return made;
}

void destroyDevice() noexcept {
  if (destroyBuilt != nullptr) {
    destroyBuilt(built);
    destroyBuilt = nullptr;
    built = nullptr;
  }
}

}  // namespace costa::replay
