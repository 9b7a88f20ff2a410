// How a node is set up: its device's constant choices (NodeSettings, constexpr in each device)
// and what the integrator gives at construction (DeviceConfig).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/device_profile.hpp"
#include "costa/lss_bit_timing.hpp"
#include "costa/pdo_channel.hpp"
#include "costa/port/can_bit_rate.hpp"
#include "costa/port/nv_storage.hpp"
#include "costa/store_commands.hpp"
#include "costa/time.hpp"

namespace costa {

/// Every storage group saved and restored by "all" (0x1010/0x1011 sub-index 1) by default: all
/// but the LSS group, which LSS stores on its own.
inline constexpr uint32_t kAllGroupsButLss = ~(groupBit(od::kGroupNone) | groupBit(od::kGroupLss));

struct NodeSettings {
  uint8_t nodeId = 1;       ///< 1..127, or 0xFF: no node-id yet (LSS only until configured).
  DeviceProfile profile{};  ///< Device-specific wire behaviour, one profile per service.
  /// Segmented and block transfer timeout (at most kLongestDelay).
  Microseconds sdoTimeout = millisecondsToMicroseconds(1000);
  /// Non-volatile storage of parameters (0x1010/0x1011) and of the LSS configuration; null: none.
  /// Without effect when parameter storage is compiled out (features::kParameterStorage).
  NvStorage* storage = nullptr;
  /// Every stored slot starts at and spans a multiple of this many bytes: the erase page of a
  /// flash part, so that erasing one slot never touches another (docs/storage.md); 1: none.
  size_t storageSlotAlignment = 1;
  uint32_t storeAllGroups = kAllGroupsButLss;    ///< groups "save" to 0x1010:01 stores
  uint32_t restoreAllGroups = kAllGroupsButLss;  ///< groups "load" to 0x1011:01 restores
  bool restoreAllIncludesLss = false;  ///< 0x1011:01 also discards the stored LSS configuration
  bool lss = false;                    ///< CiA 305 LSS slave on 0x7E5 / 0x7E4 (features::kLss)
  uint16_t lssBitRates = 0;            ///< CiA 305 table indices the controller can switch to
  /// Bit timing at power-on (CiA 305 index 3: 250 kbit/s): the rate the integrator starts the
  /// CAN controller with. A stored LSS bit timing replaces it at power-on.
  LssBitTiming bitTiming{0, 3};
  /// The device's own bit timing table (CiA 305 table selector 128): rates outside the CiA 305
  /// table (25 kbit/s) that a device sets by its own means; null: none.
  const BitRateTable* manufacturerBitRates = nullptr;
  /// The controller to re-time when the bit timing in use changes (LSS activate bit timing, a
  /// pending bit timing at reset communication or power-on); null: none, the node only records
  /// the change (and NodeEvents::onBitTimingActivation() tells the application of LSS's).
  CanBitRateControl* bitRateControl = nullptr;
  bool storedNodeIdWins = true;  ///< a stored LSS node-id replaces `nodeId` at power-on
  /// Every remote write that changes a stored entry saves its group at once (devices that keep
  /// parameters without a store command). CiA 301 saves only on 0x1010.
  bool saveParametersOnWrite = false;
  /// After every boot-up the node enters operational by itself, at its next process() call
  /// (a device that starts without an NMT master). Node::setAutomaticStart() changes it at run
  /// time, for devices where an object decides (Gefran 0x5000).
  bool automaticStart = false;
};

/// What the integrator gives a device composition at construction: the same things for every
/// device (costa-slave's --node-id, --storage and --sdo-timeout, a firmware's board).
struct DeviceConfig {
  /// The node-id when `nodeIdGiven`: 1..127, or 0xFF to start without one (LSS). Otherwise the
  /// device's own (its settings' nodeId), replaced by a node-id it stored.
  uint8_t nodeId = 0;
  /// `nodeId` was given (costa-slave --node-id): it wins over a stored node-id at power-on.
  bool nodeIdGiven = false;
  /// Non-volatile storage, or null: the device keeps its parameters in its own memory.
  NvStorage* storage = nullptr;
  /// The CAN controller to re-time on a bit rate change, or null.
  CanBitRateControl* bitRateControl = nullptr;
  /// How long the SDO server waits for the client within a transfer (costa-slave
  /// --sdo-timeout), at most kLongestDelay, or 0: the device's own (NodeSettings::sdoTimeout).
  Microseconds sdoTimeout = 0;
};

/// `settings` (a device's constant choices) with what `config` gives: the node-id when given
/// (then it wins over a stored one at power-on), the storage when given, the bit rate control,
/// the SDO timeout when given.
constexpr NodeSettings configured(NodeSettings settings, const DeviceConfig& config) noexcept {
  if (config.nodeIdGiven) {
    settings.nodeId = config.nodeId;
  }
  settings.storedNodeIdWins = !config.nodeIdGiven;
  if (config.storage != nullptr) {
    settings.storage = config.storage;
  }
  settings.bitRateControl = config.bitRateControl;
  if (config.sdoTimeout != 0U) {
    settings.sdoTimeout = config.sdoTimeout;
  }
  return settings;
}

}  // namespace costa
