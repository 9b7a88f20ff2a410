#include "fuzzed_device.hpp"

#include <optional>

#include "costa/port/memory/recording_can.hpp"
#include "devices.hpp"

namespace costa::fuzz {
namespace {

/// A composition's own invariant: its consistent() when it has one (the first overload).
struct WithoutInvariant {};
struct WithInvariant : WithoutInvariant {};
template <typename Composition, typename = decltype(&Composition::consistent)>
std::string invariantOf(const Composition& composition, WithInvariant /*unused*/) {
  char why[128] = {};
  return composition.consistent(why, sizeof(why)) ? std::string() : std::string(why);
}
template <typename Composition>
std::string invariantOf(const Composition& composition, WithoutInvariant /*unused*/) {
  (void)composition;
  return "";
}

/// A composition over its storage (declared first: it outlives the composition), rebuilt at
/// every power-on as costa-slave builds it (device_registry.cpp): the header's node-id, given
/// explicitly, or the device's own; the storage in the place of a --storage file.
template <typename Composition>
class FuzzedComposition final : public FuzzedDevice {
 public:
  FuzzedComposition(CanTransmitter& can, const PowerOnOptions& options)
      : can_(can), options_(options) {}

  void powerOn(Microseconds now) override {
    composition_.reset();
    storage_.restorePower();
    DeviceConfig config;
    config.nodeId = options_.nodeId;
    config.nodeIdGiven = options_.explicitId;
    config.storage = &storage_;
    composition_.emplace(can_, config);
    composition_->start(now);
  }
  void renew(const PowerOnOptions& options) override {
    composition_.reset();
    storage_.restorePower();
    storage_.erase(0, storage_.size());
    storage_.resetCounters();
    options_ = options;
  }
  void onFrame(const CanFrame& frame, Microseconds now) override {
    composition_->onFrame(frame, now);
  }
  Microseconds process(Microseconds now) override { return composition_->process(now); }
  Node& node() override { return composition_->node(); }
  bool hasLss() const override { return Composition::settings().lss; }
  std::string control(const char* command) override {
    char why[128] = {};
    return composition_->control(command, why, sizeof(why)) ? std::string() : why;
  }
  port::MemoryStorage& storage() override { return storage_; }
  std::string checkDevice() const override {
    return composition_ ? invariantOf(*composition_, WithInvariant{}) : std::string();
  }

 private:
  CanTransmitter& can_;
  PowerOnOptions options_;
  port::MemoryStorageOf<Composition::kStorageBytes> storage_;
  std::optional<Composition> composition_;
};

template <typename Composition>
const od::Definition* definitionOf() {
  port::RecordingCan can;
  const auto composition = std::make_unique<Composition>(can, DeviceConfig{});
  return &composition->node().dictionary().definition();
}

std::vector<FuzzedDeviceInfo> listedDevices() {
  std::vector<FuzzedDeviceInfo> devices;
  devices::forEachDevice([&devices](auto device) {
    using Composition = typename decltype(device)::Composition;
    devices.push_back(
        FuzzedDeviceInfo{device.name, definitionOf<Composition>(), Composition::kControlWords});
  });
  return devices;
}

}  // namespace

const std::vector<FuzzedDeviceInfo>& fuzzedDevices() {
  static const std::vector<FuzzedDeviceInfo> devices = listedDevices();
  return devices;
}

std::vector<std::string> fuzzedDeviceNames() {
  std::vector<std::string> names;
  for (const FuzzedDeviceInfo& device : fuzzedDevices()) {
    names.push_back(device.name);
  }
  return names;
}

const FuzzedDeviceInfo* findFuzzedDevice(const std::string& name) {
  for (const FuzzedDeviceInfo& device : fuzzedDevices()) {
    if (device.name == name) {
      return &device;
    }
  }
  return nullptr;
}

std::unique_ptr<FuzzedDevice> createFuzzedDevice(const std::string& name, CanTransmitter& can,
                                                 const PowerOnOptions& options) {
  std::unique_ptr<FuzzedDevice> made;
  devices::forEachDevice([&](auto device) {
    using Composition = typename decltype(device)::Composition;
    if (!made && name == device.name) {
      made = std::make_unique<FuzzedComposition<Composition>>(can, options);
    }
  });
  return made;
}

}  // namespace costa::fuzz
