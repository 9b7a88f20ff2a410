// All PDOs of a node: discovery of their parameter objects, validation of writes to them
// (CiA 301 7.5.2.35-7.5.2.39), dispatch of received PDOs and remote requests, SYNC and timers.
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
            size_t tpdoCapacity) noexcept;

  /// Finds the PDO communication objects in the dictionary (0x1400..0x15FF, 0x1800..0x19FF) and
  /// binds one channel to each, up to the capacities. Call once, before the first reset.
  void bind() noexcept;
  /// Reads every PDO's parameters and resolves its mapping (after a reset communication). A
  /// mapping that cannot be resolved leaves its PDO empty and is counted
  /// (unresolvableMappings()).
  void configure() noexcept;
  /// Resolves every mapping again without touching anything else (a hook was attached: the
  /// entries it covers now need more than a copy).
  void refreshMappings() noexcept;

  void start(Microseconds now) noexcept;  ///< entering operational
  void stop() noexcept;                   ///< leaving operational

  /// A data frame for RPDO `channel` (the node's routing table found it), operational. False
  /// when the PDO does not take it (not running, not valid). O(mapped entries).
  COSTA_HOT_INLINE bool receive(size_t channel, const CanFrame& frame, Microseconds now) noexcept {
    RpdoChannel& rpdo = rpdos_[channel];
    if (!running_ || !rpdo.valid()) {
      return false;
    }
    if (!rpdo.onFrame(context_, frame, now)) {
      ++rpdosRefused_;
    }
    holding_ = holding_ || rpdo.holding();
    return true;
  }
  /// A remote request for TPDO `channel`, operational. O(mapped entries).
  bool remoteRequest(size_t channel, Microseconds now) noexcept;
  /// A SYNC (operational): held RPDO data is applied, then synchronous TPDOs are sent.
  void onSync(uint8_t counter, Microseconds now, Microseconds windowEnd) noexcept;
  void process(Microseconds now) noexcept;
  Microseconds nextDeadline() const noexcept;

  /// An application event on entry (index, subIndex): every TPDO mapping it that is event-driven
  /// (254/255) or synchronous acyclic (0) will send.
  void markChanged(uint16_t index, uint8_t subIndex) noexcept;
  /// An application event for the TPDO whose communication parameter is at `index`.
  bool requestTransmission(uint16_t communicationIndex) noexcept;

  size_t rpdoCount() const noexcept { return rpdoCount_; }
  size_t tpdoCount() const noexcept { return tpdoCount_; }
  const RpdoChannel& rpdo(size_t channel) const noexcept { return rpdos_[channel]; }
  const TpdoChannel& tpdo(size_t channel) const noexcept { return tpdos_[channel]; }
  /// RPDOs not written because an entry was refused, since construction.
  uint32_t rpdosRefused() const noexcept { return rpdosRefused_; }
  /// Mappings that could not be resolved at configuration (the PDO then carries nothing).
  uint32_t unresolvableMappings() const noexcept { return unresolvableMappings_; }

  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;

 private:
  RpdoChannel* findRpdo(uint16_t communicationIndex) noexcept;
  TpdoChannel* findTpdo(uint16_t communicationIndex) noexcept;
  /// write() for a parameter of `channel` (an RpdoChannel or a TpdoChannel).
  template <typename Channel>
  AbortCode writeParameter(Channel& channel, bool mapping, od::ObjectDictionary& dictionary,
                           const od::EntryRef& ref, const uint8_t* data, size_t length) noexcept;
  AbortCode checkCommunicationWrite(bool receive, bool currentlyValid, uint32_t currentCanId,
                                    uint8_t subIndex, const uint8_t* data,
                                    size_t length) const noexcept;
  AbortCode checkMappingWrite(bool receive, bool pdoValid, const od::EntryRef& ref,
                              const uint8_t* data, size_t length) const noexcept;

  PdoContext& context_;
  RpdoChannel* rpdos_;
  size_t rpdoCapacity_;
  size_t rpdoCount_ = 0;
  TpdoChannel* tpdos_;
  size_t tpdoCapacity_;
  size_t tpdoCount_ = 0;
  bool running_ = false;
  bool holding_ = false;  ///< some RPDO holds data for the next SYNC
  uint32_t rpdosRefused_ = 0;
  uint32_t unresolvableMappings_ = 0;
};

}  // namespace costa
