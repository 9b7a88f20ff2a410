#include "fuzzed_device.hpp"

#include <optional>

#include "example_target.hpp"
#include "gefran_target.hpp"
#include "gra_od.hpp"
#include "grn_od.hpp"
#include "solo_target.hpp"

namespace costa::fuzz {
namespace {

/// Bytes of the example's storage: the size costa-slave gives its --storage file.
constexpr size_t kExampleStorageBytes = 16384;

/// The parts every composition shares: the storage (declared first: it outlives the
/// composition) and the composition itself, rebuilt at every power-on.
template <typename Composition, size_t kStorageBytes>
class FuzzedComposition : public FuzzedDevice {
 public:
  FuzzedComposition(CanTransmitter& can, const PowerOnOptions& options)
      : can_(can), options_(options) {}

  void powerOn(Microseconds now) override {
    composition_.reset();
    storage_.restorePower();
    build();
    beforeStart();
    composition_->start(now);
  }
  void onFrame(const CanFrame& frame, Microseconds now) override {
    composition_->onFrame(frame, now);
  }
  Microseconds process(Microseconds now) override { return composition_->process(now); }
  Node& node() override { return composition_->node(); }
  port::MemoryStorage& storage() override { return storage_; }

 protected:
  /// Emplaces the composition.
  virtual void build() = 0;
  /// Between build and start (inputs that exist before the power comes).
  virtual void beforeStart() {}

  /// The node-id given to the composition: the header's, or the device's own.
  uint8_t nodeId(uint8_t own) const { return options_.nodeId != 0U ? options_.nodeId : own; }

  CanTransmitter& can_;
  PowerOnOptions options_;
  port::MemoryStorageOf<kStorageBytes> storage_;
  std::optional<Composition> composition_;
};

class FuzzedExample final : public FuzzedComposition<example::ExampleTarget, kExampleStorageBytes> {
 public:
  using FuzzedComposition::FuzzedComposition;
  bool hasLss() const override { return true; }

 private:
  void build() override {
    // As costa-slave builds it (device_registry.cpp).
    NodeSettings settings = example::ExampleTarget::settings(nodeId(1), &storage_);
    settings.storedNodeIdWins = !options_.explicitId;
    composition_.emplace(can_, settings);
  }
};

class FuzzedSolo final
    : public FuzzedComposition<solo::SoloTarget, solo::SoloTarget::kEepromBytes> {
 public:
  using FuzzedComposition::FuzzedComposition;
  bool hasLss() const override { return false; }

 private:
  void build() override { composition_.emplace(can_, nodeId(1), &storage_, options_.explicitId); }
};

template <typename Values, typename Capacity>
class FuzzedGefran final
    : public FuzzedComposition<gefran::GefranTarget<Values, Capacity>,
                               gefran::GefranTarget<Values, Capacity>::kEepromBytes> {
  using Base = FuzzedComposition<gefran::GefranTarget<Values, Capacity>,
                                 gefran::GefranTarget<Values, Capacity>::kEepromBytes>;

 public:
  FuzzedGefran(const od::Definition& definition, CanTransmitter& can, const PowerOnOptions& options)
      : Base(can, options), definition_(definition) {}
  bool hasLss() const override { return true; }

  void setHallReadings(uint16_t chip1, uint16_t chip2) override {
    readings_[0] = chip1;
    readings_[1] = chip2;
    this->composition_->sensors().setRaw(chip1, chip2);
  }
  void setHallFaults(uint8_t faults) override {
    faults_ = faults;
    applyFaults();
  }

 private:
  void build() override {
    this->composition_.emplace(definition_, this->can_, this->nodeId(gefran::kFactoryNodeId),
                               &this->storage_, this->options_.explicitId);
  }
  void beforeStart() override {
    this->composition_->sensors().setRaw(readings_[0], readings_[1]);
    applyFaults();
  }
  void applyFaults() {
    gefran::SimulatedHallSensors& sensors = this->composition_->sensors();
    sensors.setFault(0xFF, false);
    sensors.setFault(faults_, true);
  }

  const od::Definition& definition_;
  uint16_t readings_[2] = {};
  uint8_t faults_ = 0;
};

}  // namespace

const std::vector<std::string>& fuzzedDeviceNames() {
  static const std::vector<std::string> names = {"example", "solo", "gra", "grn"};
  return names;
}

const od::Definition* fuzzedDefinition(const std::string& name) {
  if (name == "example") {
    return &gen::example::kDefinition;
  }
  if (name == "solo") {
    return &gen::solo::kDefinition;
  }
  if (name == "gra") {
    return &gen::gra::kDefinition;
  }
  if (name == "grn") {
    return &gen::grn::kDefinition;
  }
  return nullptr;
}

std::unique_ptr<FuzzedDevice> createFuzzedDevice(const std::string& name, CanTransmitter& can,
                                                 const PowerOnOptions& options) {
  if (name == "example") {
    return std::make_unique<FuzzedExample>(can, options);
  }
  if (name == "solo") {
    return std::make_unique<FuzzedSolo>(can, options);
  }
  if (name == "gra") {
    return std::make_unique<FuzzedGefran<gen::gra::Values, gen::gra::Capacity>>(
        gen::gra::kDefinition, can, options);
  }
  if (name == "grn") {
    return std::make_unique<FuzzedGefran<gen::grn::Values, gen::grn::Capacity>>(
        gen::grn::kDefinition, can, options);
  }
  return nullptr;
}

}  // namespace costa::fuzz
