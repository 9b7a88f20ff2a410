// A device target as the fuzzer drives it: the composition that firmware and costa-slave use
// (targets/devices.hpp), over in-memory non-volatile storage that outlives it, so that a power
// cycle builds a fresh composition which loads what the previous one stored.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <memory>
#include <string>
#include <vector>

#include "costa/node.hpp"
#include "costa/od/definition.hpp"
#include "costa/port/can_port.hpp"
#include "costa/port/memory/memory_storage.hpp"
#include "fuzz_events.hpp"

namespace costa::fuzz {

class FuzzedDevice {
 public:
  virtual ~FuzzedDevice() = default;

  /// Builds the composition (again, after a power cycle) and starts it at `now`. What the
  /// simulation commands set (a shaft's angle, a fault) starts over with it.
  virtual void powerOn(Microseconds now) = 0;
  /// A new device for the next input, in the same memory: no composition, erased storage with
  /// power and fresh counters, `options` for the power-ons to come.
  virtual void renew(const PowerOnOptions& options) = 0;
  virtual void onFrame(const CanFrame& frame, Microseconds now) = 0;
  /// The composition's process(): node and device behaviour; returns the next deadline.
  virtual Microseconds process(Microseconds now) = 0;
  virtual Node& node() = 0;
  /// The device runs an LSS slave (may send on 0x7E4): its settings().lss.
  virtual bool hasLss() const = 0;
  /// A simulation command: the composition's control(). "" when done, else why not.
  virtual std::string control(const char* command) = 0;

  /// The device's non-volatile memory.
  virtual port::MemoryStorage& storage() = 0;
  /// "" when the device's own invariant holds (a composition's optional
  /// `bool consistent(char* why, size_t whySize) const`, such as a drive's status word that
  /// shows its state), else why not. "" for a composition without one.
  virtual std::string checkDevice() const = 0;
};

/// What the fuzzer knows of a device of the list without running it.
struct FuzzedDeviceInfo {
  std::string name;
  const od::Definition* definition;  ///< its generated dictionary
  std::string controlWords;          ///< the words of its simulation commands (kControlWords)
};

/// Every device of the list (targets/devices.hpp), in its order.
const std::vector<FuzzedDeviceInfo>& fuzzedDevices();
/// Their names: example, solo, gra, grn, ...
std::vector<std::string> fuzzedDeviceNames();
/// The device `name`; null for an unknown name.
const FuzzedDeviceInfo* findFuzzedDevice(const std::string& name);

/// The device `name` on `can`, not yet powered on; null for an unknown name.
std::unique_ptr<FuzzedDevice> createFuzzedDevice(const std::string& name, CanTransmitter& can,
                                                 const PowerOnOptions& options);

}  // namespace costa::fuzz
