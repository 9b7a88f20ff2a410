// The behaviour behind the example device's manufacturer objects.
//
//   0x2001 Uptime seconds   counts seconds since the last reset application.
//   0x2002 Command          1 = restart the uptime count; 2 = no operation;
//                           3 = run the self-test. The example has no sensor fitted, so the
//                           self-test always fails and the write aborts with 0x08000000.
//   0x2010 Operating mode   may only be changed in pre-operational; in operational or stopped
//                           the write aborts with 0x08000022.
#pragma once

#include "costa/node.hpp"

namespace costa::example {

class ExampleDevice : public ObjectHook, public NodeEvents {
 public:
  static constexpr uint16_t kUptime = 0x2001;
  static constexpr uint16_t kCommand = 0x2002;
  static constexpr uint16_t kOperatingMode = 0x2010;

  /// Attaches itself to `node` (hooks and events). Call before `node.start()`. `serialNumber`
  /// goes into 0x1018:04 (so that several example nodes can be told apart by LSS).
  explicit ExampleDevice(Node& node, uint32_t serialNumber = 1) noexcept;

  /// Updates the uptime object. Returns the time of the next update.
  Microseconds process(Microseconds now) noexcept;

  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;
  void onResetApplication() noexcept override;
  void onResetCommunication() noexcept override;

 private:
  Node& node_;
  uint32_t serialNumber_;
  Microseconds epoch_ = 0;
};

}  // namespace costa::example
