// A device target as the fuzzer drives it: the composition that firmware and costa-slave use,
// over in-memory non-volatile storage that outlives it, so that a power cycle builds a fresh
// composition which loads what the previous one stored.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <memory>
#include <string>
#include <vector>

#include "costa/node.hpp"
#include "costa/port/can_port.hpp"
#include "costa/port/memory/memory_storage.hpp"
#include "fuzz_events.hpp"

namespace costa::fuzz {

class FuzzedDevice {
 public:
  virtual ~FuzzedDevice() = default;

  /// Builds the composition (again, after a power cycle) and starts it at `now`.
  virtual void powerOn(Microseconds now) = 0;
  virtual void onFrame(const CanFrame& frame, Microseconds now) = 0;
  /// The composition's process(): node and device behaviour; returns the next deadline.
  virtual Microseconds process(Microseconds now) = 0;
  virtual Node& node() = 0;
  /// The device runs an LSS slave (may send on 0x7E4).
  virtual bool hasLss() const = 0;
  /// Hall chip inputs of a GRA/GRN; other devices ignore them. Kept across power cycles (the
  /// shaft does not move when the power goes).
  virtual void setHallReadings(uint16_t chip1, uint16_t chip2) {
    (void)chip1;
    (void)chip2;
  }
  virtual void setHallFaults(uint8_t faults) { (void)faults; }

  /// The device's non-volatile memory.
  virtual port::MemoryStorage& storage() = 0;
};

/// Names the fuzzer knows: example, solo, gra, grn.
const std::vector<std::string>& fuzzedDeviceNames();

/// The generated dictionary of the device `name`; null for an unknown name.
const od::Definition* fuzzedDefinition(const std::string& name);

/// The device `name` on `can`, not yet powered on; null for an unknown name.
std::unique_ptr<FuzzedDevice> createFuzzedDevice(const std::string& name, CanTransmitter& can,
                                                 const PowerOnOptions& options);

}  // namespace costa::fuzz
