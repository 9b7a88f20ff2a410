// All PDOs of a node: discovery of their parameter objects, validation of writes to them
// (CiA 301 7.5.2.35-7.5.2.39), dispatch of received PDOs and remote requests, SYNC and timers.
//
// Context: the one that runs the node (Node calls every function here), never an interrupt; not
// reentrant. No allocation: channels live in caller-owned storage (NodeMemory). A mapping is
// resolved when it is configured (configure(), a write to its parameters, refreshMappings()),
// so a PDO frame costs O(mapped entries) copies, plus each hooked or range-limited entry's
// check. Failures are counted, never reported by blocking: an RPDO refused as a whole
// (rpdosRefused()), a mapping that cannot be resolved (unresolvableMappings()); a write to a
// PDO parameter that CiA 301 forbids returns its abort code.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/hot_path.hpp"
#include "costa/object_hook.hpp"
#include "costa/pdo_channel.hpp"
#include "costa/rpdo_channel.hpp"
#include "costa/tpdo_channel.hpp"

namespace costa {

class PdoEngine : public ObjectHook {
 public:
  static constexpr uint16_t kFirst = 0x1400;
  static constexpr uint16_t kLast = 0x1BFF;

  PdoEngine(PdoContext& context, RpdoChannel* rpdos, size_t rpdoCapacity, TpdoChannel* tpdos,
            size_t tpdoCapacity) noexcept
      : context_(context),
        rpdos_(rpdos),
        rpdoCapacity_(rpdoCapacity),
        tpdos_(tpdos),
        tpdoCapacity_(tpdoCapacity) {}

  /// Finds the PDO communication objects in the dictionary (0x1400..0x15FF, 0x1800..0x19FF) and
  /// binds one channel to each, up to the capacities (PDOs beyond them are not served). Call
  /// once, before the first reset. O(objects).
  void bind() noexcept;
  /// Reads every PDO's parameters and resolves its mapping (after a reset communication). A
  /// mapping that cannot be resolved leaves its PDO empty and is counted
  /// (unresolvableMappings()). O(PDOs x mapped entries x log objects).
  void configure() noexcept;
  /// Resolves every mapping again without touching anything else (a hook was attached: the
  /// entries it covers now need more than a copy). O(PDOs x mapped entries x log objects).
  void refreshMappings() noexcept;

  /// Entering operational: timers start; TPDOs of the profile's choice go out. O(PDOs).
  void start(Microseconds now) noexcept;
  /// Leaving operational: timers stop, data held for a SYNC is dropped. O(PDOs).
  void stop() noexcept;

  /// A data frame for RPDO `channel` (the node's routing table found it), operational. False
  /// when the PDO does not take it (not running, not valid). A frame of the wrong length raises
  /// EMCY 0x8210/0x8220; a refused entry leaves every entry as it was, fires no event and is
  /// counted (rpdosRefused()). O(mapped entries).
  COSTA_HOT_INLINE bool receive(size_t channel, const CanFrame& frame, Microseconds now) noexcept {
    RpdoChannel& rpdo = rpdos_[channel];
    if (!running_ || !rpdo.valid()) {
      return false;
    }
    if (!rpdo.onFrame(context_, frame, now)) {
      ++rpdosRefused_;
      rpdo.withdrawAnswer(context_);
    }
    holding_ = holding_ || rpdo.holding();
    return true;
  }
  /// A remote request for TPDO `channel`, operational. False when the PDO does not answer it
  /// (not valid, RTR not allowed, a type that does not answer). O(mapped entries).
  [[nodiscard]] bool remoteRequest(size_t channel, Microseconds now) noexcept;
  /// A SYNC (operational): held RPDO data is applied, then synchronous TPDOs are sent; a TPDO
  /// still queued at `windowEnd` is dropped and counted (TransmitPath::expired()). O(PDOs).
  void onSync(uint8_t counter, Microseconds now, Microseconds windowEnd) noexcept;
  /// Timers due at `now`: event timers, inhibit times, RPDO deadlines (EMCY 0x8250). O(PDOs).
  void process(Microseconds now) noexcept;
  /// The earliest timer of any PDO, kNever when none runs. O(PDOs).
  Microseconds nextDeadline() const noexcept;

  /// An application event on entry (index, subIndex): every TPDO mapping it that is event-driven
  /// (254/255) or synchronous acyclic (0) will send (subject to its inhibit time). Nothing
  /// happens outside operational. O(TPDOs x mapped entries).
  void markChanged(uint16_t index, uint8_t subIndex) noexcept;
  /// An application event for the TPDO whose communication parameter is at `index`. False when
  /// there is no such TPDO. O(TPDOs).
  [[nodiscard]] bool requestTransmission(uint16_t communicationIndex) noexcept;

  size_t rpdoCount() const noexcept { return rpdoCount_; }
  size_t tpdoCount() const noexcept { return tpdoCount_; }
  const RpdoChannel& rpdo(size_t channel) const noexcept { return rpdos_[channel]; }
  const TpdoChannel& tpdo(size_t channel) const noexcept { return tpdos_[channel]; }
  /// RPDOs not written because an entry was refused, since construction.
  uint32_t rpdosRefused() const noexcept { return rpdosRefused_; }
  /// Mappings that could not be resolved at configuration (the PDO then carries nothing).
  uint32_t unresolvableMappings() const noexcept { return unresolvableMappings_; }

  /// A remote write to a PDO parameter (0x1400..0x1BFF) under CiA 301's rules: a valid PDO's
  /// CAN-ID cannot change, 29-bit and restricted CAN-IDs are refused (0x06090030); its mapping
  /// changes only while the PDO is invalid and sub-index 0 is 0 (0x08000022); more than 64 bits
  /// 0x06040042; an entry that does not exist 0x06020000 / 0x06090011, is not mappable
  /// 0x06040041, or has another length 0x06040043. Then the channel is configured again.
  /// O(mapped entries x log objects).
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;

 private:
  /// The RPDO (`receive`) or TPDO whose communication parameter is at `communicationIndex`,
  /// and its number in `*number`; nullptr when there is none.
  const PdoChannel* findChannel(bool receive, uint16_t communicationIndex,
                                size_t* number) const noexcept;
  /// Configures RPDO (`receive`) or TPDO `number` from its parameters; a TPDO restarts when
  /// running, else stops. Counts a mapping that cannot be resolved.
  void configureChannel(bool receive, size_t number) noexcept;
  TpdoChannel* findTpdo(uint16_t communicationIndex) noexcept;
  /// The refusal of a write to `ref`, a parameter of `channel` (an RPDO's when `receive`), or
  /// kNone: a communication parameter's, a mapping parameter's.
  AbortCode checkCommunicationWrite(const PdoChannel& channel, bool receive,
                                    const od::EntryRef& ref, const uint8_t* data,
                                    size_t length) const noexcept;
  AbortCode checkMappingWrite(const PdoChannel& channel, bool receive, const od::EntryRef& ref,
                              const uint8_t* data, size_t length) const noexcept;

  PdoContext& context_;
  // The two flags first, within reach of Thumb-1's short byte offsets.
  bool running_ = false;
  bool holding_ = false;  ///< some RPDO holds data for the next SYNC
  RpdoChannel* rpdos_;
  size_t rpdoCapacity_;
  size_t rpdoCount_ = 0;
  TpdoChannel* tpdos_;
  size_t tpdoCapacity_;
  size_t tpdoCount_ = 0;
  uint32_t rpdosRefused_ = 0;
  uint32_t unresolvableMappings_ = 0;
};

}  // namespace costa
