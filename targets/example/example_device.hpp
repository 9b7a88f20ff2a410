// The behaviour behind the example device's manufacturer objects.
//
//   0x2001 Uptime seconds   counts seconds since the last reset application.
//   0x2002 Command          1 = restart the uptime count; 2 = no operation;
//                           3 = run the self-test. The example has no sensor fitted, so the
//                           self-test always fails and the write aborts with 0x08000000.
//   0x2008 Scratch pad      a DOMAIN of up to 12 KiB held by the device, streamed through the
//                           hook: a download stores the bytes and their length, an upload
//                           returns them. A larger download aborts with 0x06070012 (at once
//                           when its size is indicated, leaving the content). Once data flows
//                           the old content is gone: an aborted download leaves the pad empty.
//                           Emptied by reset application.
//   0x2010 Operating mode   may only be changed in pre-operational; in operational or stopped
//                           the write aborts with 0x08000022.
//   0x2012 Clock of day     the node's clock of day (TIME), example_clock.hpp.
//   0x2013 Last emergency   what the EMCY consumer (0x1028) heard last: the producer's node-id,
//          received         error code and error register, and how many emergencies it heard.
#pragma once

#include "costa/node.hpp"
#include "example_clock.hpp"

namespace costa::example {

class ExampleDevice : public ObjectHook, public NodeEvents {
 public:
  static constexpr uint16_t kUptime = 0x2001;
  static constexpr uint16_t kCommand = 0x2002;
  static constexpr uint16_t kScratchPad = 0x2008;
  static constexpr uint16_t kOperatingMode = 0x2010;
  static constexpr uint16_t kLastEmergency = 0x2013;
  static constexpr size_t kScratchPadCapacity = size_t{12} * 1024U;

  /// Attaches itself to `node` (hooks and events). Call before `node.start()`. `serialNumber`
  /// goes into 0x1018:04 (so that several example nodes can be told apart by LSS).
  explicit ExampleDevice(Node& node, uint32_t serialNumber = 1) noexcept;

  /// Updates the uptime object. Returns the time of the next update.
  Microseconds process(Microseconds now) noexcept;

  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;
  AbortCode readStream(od::ObjectDictionary& dictionary, const od::EntryRef& ref, size_t offset,
                       uint8_t* destination, size_t capacity, size_t* produced,
                       size_t* totalSize) noexcept override;
  AbortCode writeStream(od::ObjectDictionary& dictionary, const od::EntryRef& ref, size_t offset,
                        const uint8_t* source, size_t length, bool last,
                        size_t indicatedSize) noexcept override;
  void abortWriteStream(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                        AbortCode reason) noexcept override;
  void onResetApplication() noexcept override;
  void onResetCommunication() noexcept override;
  void onEmcyReceived(const EmcyMessage& emcy) noexcept override;

  /// Every hook and the listener found room in the node (its NodeStatistics count refusals).
  bool attached() const noexcept { return attached_; }

  /// The scratch pad's content (0x2008).
  const uint8_t* scratchPad() const noexcept { return scratchPad_; }
  size_t scratchPadLength() const noexcept { return scratchPadLength_; }

 private:
  void restartUptime() noexcept;

  Node& node_;
  ExampleClock clock_;
  uint32_t serialNumber_;
  Microseconds secondStart_ = 0;  ///< start of the second being counted
  uint32_t uptime_ = 0;           ///< whole seconds since the last reset application
  /// Only the first scratchPadLength_ bytes mean something (not initialised: 12 KiB).
  uint8_t scratchPad_[kScratchPadCapacity];  // NOLINT(cppcoreguidelines-pro-type-member-init)
  size_t scratchPadLength_ = 0;
  bool receiving_ = false;  ///< A download has started overwriting the scratch pad.
  bool attached_;           ///< last: every other member is ready when the node gets the hooks
};

}  // namespace costa::example
