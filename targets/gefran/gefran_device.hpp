// The behaviour behind a GRA/GRN's objects (docs/errata-gefran.md): the two angles from the hall
// chips into 0x2000, 0x2011 and the TPDO bytes 0x2110, the error code 0x4001 with its EMCY and
// the error behaviour 0x4000, the automatic start 0x5000, the checks of 0x2100/0x2101, and the
// LSS parameters 0x5999 (views of the node's LSS configuration).
#pragma once

#include <stddef.h>

#include "costa/node.hpp"
#include "hall_sensors.hpp"

namespace costa::gefran {

/// The factory node-id (E1).
inline constexpr uint8_t kFactoryNodeId = 0x7F;

/// The bit rates of the manual's list (lines 611-617, E26) as CiA 305 table indices: 1000, 800,
/// 500, 250, 125 and 50 kbit/s.
inline constexpr uint16_t kListedBitRates =
    (1U << 0) | (1U << 1) | (1U << 2) | (1U << 3) | (1U << 4) | (1U << 6);

/// Where the values the device refreshes on every call live: members of the generated value
/// block of either variant (gefranValues()), so that no call looks them up by index.
struct GefranValues {
  uint16_t* rawValues;          ///< 0x2000:01..02
  uint16_t* processData;        ///< 0x2011:01..02
  uint32_t* processDataBoth;    ///< 0x2011:03
  const uint16_t* resolution;   ///< 0x2100:01..02
  const uint16_t* zeroPoint;    ///< 0x2101:01..02
  const uint8_t* clockwise;     ///< 0x2102:01..02
  uint8_t* outputBytes;         ///< 0x2110:01..04
  uint8_t* errorCode;           ///< 0x4001
  const uint8_t* littleEndian;  ///< 0x5001
};

/// The members of a generated value block (gra or grn: the same objects).
template <typename Values>
GefranValues gefranValues(Values& v) noexcept {
  static_assert(offsetof(typename Values::X2011AngleSensorProcessData, angle_2_process_data) ==
                    sizeof(uint16_t),
                "0x2011:01 and :02 side by side");
  static_assert(sizeof(typename Values::X2110Angle1AndAngle2Values) == 4U,
                "0x2110:01..04 side by side");
  return GefranValues{v.x2000_angle_value.item,
                      &v.x2011_angle_sensor_process_data.angle_1_process_data,
                      &v.x2011_angle_sensor_process_data.angle_1_and_2_process_data,
                      v.x2100_angle_resolution.item,
                      v.x2101_angle_zero_degree_point.item,
                      v.x2102_angle_clockwise.item,
                      &v.x2110_angle_1_and_angle_2_values.angle_1_output_byte_0,
                      &v.x4001_error_code,
                      &v.x5001_pdo_coding};
}

class GefranDevice : public ObjectHook, public NodeEvents {
 public:
  GefranDevice(Node& node, const GefranValues& values, HallSensors& sensors) noexcept;

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
  /// What the angle objects are computed from (the last time: valid true).
  struct AngleInputs {
    uint16_t raw[2];
    uint16_t resolution[2];
    uint16_t zeroPoint[2];
    uint8_t clockwise[2];
    uint8_t littleEndian;
    bool valid;
    bool operator==(const AngleInputs& other) const noexcept {
      return raw[0] == other.raw[0] && raw[1] == other.raw[1] &&
             resolution[0] == other.resolution[0] && resolution[1] == other.resolution[1] &&
             zeroPoint[0] == other.zeroPoint[0] && zeroPoint[1] == other.zeroPoint[1] &&
             clockwise[0] == other.clockwise[0] && clockwise[1] == other.clockwise[1] &&
             littleEndian == other.littleEndian && valid == other.valid;
    }
  };

  void updateAngles() noexcept;
  void updateErrors() noexcept;
  uint32_t value(uint16_t index, uint8_t sub) const noexcept;

  Node& node_;
  GefranValues values_;
  AngleInputs inputs_{};
  HallSensors& sensors_;
  uint8_t storedFaults_ = 0;    ///< faults found in stored parameters since power-on
  uint8_t reportedFaults_ = 0;  ///< 0x4001 bits whose EMCY condition is raised
  bool attached_;               ///< last: every other member is ready when the node gets the hooks
};

}  // namespace costa::gefran
