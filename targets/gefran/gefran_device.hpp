// The behaviour behind a GRA/GRN's objects (docs/errata-gefran.md): the two angles from the hall
// chips into 0x2000, 0x2011 and the TPDO bytes 0x2110, the error code 0x4001 with its EMCY and
// the error behaviour 0x4000, the automatic start 0x5000, the checks of 0x2100/0x2101, and the
// LSS parameters 0x5999 (views of the node's LSS configuration).
#pragma once

#include "costa/node.hpp"
#include "hall_sensors.hpp"

namespace costa::gefran {

/// The factory node-id (E1).
inline constexpr uint8_t kFactoryNodeId = 0x7F;

/// The bit rates of the manual's list (lines 611-617, E26) as CiA 305 table indices: 1000, 800,
/// 500, 250, 125 and 50 kbit/s.
inline constexpr uint16_t kListedBitRates =
    (1U << 0) | (1U << 1) | (1U << 2) | (1U << 3) | (1U << 4) | (1U << 6);

class GefranDevice : public ObjectHook, public NodeEvents {
 public:
  GefranDevice(Node& node, HallSensors& sensors) noexcept;

  /// Brings the angle objects and the error code up to date, starts the node after a boot-up
  /// when 0x5000 = 1. Returns kNever (nothing is timed here).
  Microseconds process(Microseconds now) noexcept;

  /// Every hook and the listener found room in the node (its NodeStatistics count refusals).
  bool attached() const noexcept { return attached_; }

  AbortCode prepareRead(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                        const ReadRequest& request) noexcept override;
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;
  void onResetCommunication() noexcept override;
  void onResetApplication() noexcept override;
  void onStoredParametersInvalid(uint8_t group, StoreResult result) noexcept override;

 private:
  void updateAngles() noexcept;
  void updateErrors() noexcept;
  uint32_t value(uint16_t index, uint8_t sub) const noexcept;

  Node& node_;
  HallSensors& sensors_;
  uint8_t storedFaults_ = 0;    ///< faults found in stored parameters since power-on
  uint8_t reportedFaults_ = 0;  ///< 0x4001 bits whose EMCY condition is raised
  bool attached_;               ///< last: every other member is ready when the node gets the hooks
};

}  // namespace costa::gefran
