// The device targets: the one C++ list of devices, with the names and order of
// targets/devices.cmake (the test device_lists compares the two, and every consumer with them).
// Freestanding: firmware images and the firmware transcript replayer read it too.
//
// Each line: X(name, composition). A composition holds a device's node and behaviour and has
//   static constexpr NodeSettings settings() noexcept;   // its constant choices
//   Composition(CanTransmitter& can, const DeviceConfig& config) noexcept;
//   void start(Microseconds now) noexcept;
//   void onFrame(const CanFrame& frame, Microseconds now) noexcept;
//   Microseconds process(Microseconds now) noexcept;
//   bool control(const char* command, char* why, size_t whySize) noexcept;  // device_control.hpp
//   <NodeInstance>& node() noexcept;
//   bool attached() const noexcept;  // its hooks and listeners found room in the node
//   static const od::NameTable& names() noexcept;  // host programs only
//   kSummary (one line), kStorageBytes (its non-volatile memory), kControlWords (its command
//   words, space-separated, "" for none); optionally kHighestNodeId, when the device takes
//   fewer node-ids than CiA 301's 1..127 (highestNodeId()).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <type_traits>

#include "example_target.hpp"
#include "gefran_target.hpp"
#include "mseries_target.hpp"
#include "santeng_target.hpp"
#include "solo_target.hpp"

// NOLINTBEGIN(cppcoreguidelines-macro-usage,bugprone-macro-parentheses): an X-macro, the one
// list that both the compiler (types) and the build of each firmware image (a name) can expand;
// its arguments are a name and a type, which no parentheses may enclose.
#define COSTA_DEVICES(X)                      \
  X(example, ::costa::example::ExampleTarget) \
  X(solo, ::costa::solo::SoloTarget)          \
  X(gra, ::costa::gefran::GraTarget)          \
  X(grn, ::costa::gefran::GrnTarget)          \
  X(santeng, ::costa::santeng::SantengTarget) \
  X(mseries, ::costa::mseries::MSeriesTarget)

namespace costa::devices {

/// Each device's composition under its name: costa::devices::gra is gefran::GraTarget.
#define COSTA_DEVICE_ALIAS(name, Composition) using name = Composition;
COSTA_DEVICES(COSTA_DEVICE_ALIAS)
#undef COSTA_DEVICE_ALIAS

/// A device of the list: its name, and its composition as a type.
template <typename C>
struct Device {
  using Composition = C;
  const char* name;
};

/// Calls visit(Device<Composition>{name}) for every device, in the list's order.
template <typename Visitor>
constexpr void forEachDevice(Visitor&& visit) {
#define COSTA_VISIT_DEVICE(name, Composition) visit(Device<Composition>{#name});
  COSTA_DEVICES(COSTA_VISIT_DEVICE)
#undef COSTA_VISIT_DEVICE
}
// NOLINTEND(cppcoreguidelines-macro-usage,bugprone-macro-parentheses)

/// The largest node-id a composition takes: its kHighestNodeId, else 127 (CiA 301).
template <typename Composition, typename = void>
struct HighestNodeId {
  static constexpr uint8_t kValue = 127;
};
template <typename Composition>
struct HighestNodeId<Composition, std::void_t<decltype(Composition::kHighestNodeId)>> {
  static constexpr uint8_t kValue = Composition::kHighestNodeId;
};
template <typename Composition>
constexpr uint8_t highestNodeId() noexcept {
  return HighestNodeId<Composition>::kValue;
}

/// How many devices the list has.
inline constexpr size_t kCount = [] {
  size_t count = 0;
  forEachDevice([&count](auto) { ++count; });
  return count;
}();

/// True when `name` (NUL-terminated) is the device's name.
constexpr bool isNamed(const char* deviceName, const char* name) noexcept {
  size_t i = 0;
  for (; deviceName[i] != '\0'; ++i) {
    if (name[i] != deviceName[i]) {
      return false;
    }
  }
  return name[i] == '\0';
}

}  // namespace costa::devices
