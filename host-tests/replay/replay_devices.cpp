#include "replay_devices.hpp"

#include <new>

#include "example_target.hpp"
#include "gefran_control.hpp"
#include "gefran_target.hpp"
#include "gra_od.hpp"
#include "grn_od.hpp"
#include "solo_target.hpp"

namespace costa::replay {
namespace {

/// A GRA or GRN with its simulation commands (costa-slave's controlGefran).
template <typename Values, typename Capacity>
class ReplayedGefran final : public ReplayedComposition<gefran::GefranTarget<Values, Capacity>> {
 public:
  using ReplayedComposition<gefran::GefranTarget<Values, Capacity>>::ReplayedComposition;

  bool control(const char* command, Text& why) noexcept override {
    const gefran::ParsedControl parsed = gefran::parseControl(command);
    if (parsed.error != gefran::ControlError::kNone) {
      char message[96];
      const size_t length = gefran::describeControlError(parsed, message, sizeof(message));
      why.append(message, length < sizeof(message) ? length : sizeof(message) - 1U);
      return false;
    }
    auto& target = this->composition();
    gefran::applyControl(parsed.command, target.sensors());
    target.process(target.node().now());
    return true;
  }
};

using ExampleDevice = ReplayedComposition<example::ExampleTarget>;
using SoloDevice = ReplayedComposition<solo::SoloTarget>;
using GraDevice = ReplayedGefran<gen::gra::Values, gen::gra::Capacity>;
using GrnDevice = ReplayedGefran<gen::grn::Values, gen::grn::Capacity>;

constexpr size_t larger(size_t a, size_t b) {
  return a > b ? a : b;
}
constexpr size_t kSlotBytes = larger(larger(sizeof(ExampleDevice), sizeof(SoloDevice)),
                                     larger(sizeof(GraDevice), sizeof(GrnDevice)));
constexpr size_t kSlotAlignment = larger(larger(alignof(ExampleDevice), alignof(SoloDevice)),
                                         larger(alignof(GraDevice), alignof(GrnDevice)));

alignas(kSlotAlignment) unsigned char slot[kSlotBytes];
void* built = nullptr;  ///< the device in `slot`
void (*destroyBuilt)(void*) noexcept = nullptr;

template <typename Device>
void destroy(void* device) noexcept {
  static_cast<Device*>(device)->~Device();
}

template <typename Device, typename... Args>
ReplayDevice& build(Args&... args) noexcept {
  static_assert(sizeof(Device) <= kSlotBytes, "the slot holds every device");
  Device* device = ::new (static_cast<void*>(slot)) Device(args...);
  built = device;
  destroyBuilt = &destroy<Device>;
  return *device;
}

}  // namespace

ReplayDevice& buildDevice(DeviceKind device, uint8_t nodeId, CanTransmitter& can) noexcept {
  destroyDevice();
  NvStorage* const noStorage = nullptr;  // no --storage: the device's own memory
  const bool explicitNodeId = true;      // --node-id given: it wins over a stored one
  switch (device) {
    case DeviceKind::kExample: {
      NodeSettings settings = example::ExampleTarget::settings(nodeId, noStorage);
      settings.storedNodeIdWins = !explicitNodeId;
      return build<ExampleDevice>(can, settings);
    }
    case DeviceKind::kSolo: return build<SoloDevice>(can, nodeId, noStorage, explicitNodeId);
    case DeviceKind::kGra:
      return build<GraDevice>(gen::gra::kDefinition, can, nodeId, noStorage, explicitNodeId);
    case DeviceKind::kGrn: break;
  }
  return build<GrnDevice>(gen::grn::kDefinition, can, nodeId, noStorage, explicitNodeId);
}

void destroyDevice() noexcept {
  if (destroyBuilt != nullptr) {
    destroyBuilt(built);
    destroyBuilt = nullptr;
    built = nullptr;
  }
}

}  // namespace costa::replay
