// The two hall chips of a GRA/GRN: where firmware reads its sensors. The Linux slave and the
// tests use SimulatedHallSensors, whose shaft and faults are set from outside.
#pragma once

#include <stdint.h>

namespace costa::gefran {

/// Bits of the error code 0x4001 (manual lines 278-286).
enum SensorFault : uint8_t {
  kChip1Error = 0x01,
  kChip2Error = 0x02,
  kAngleMismatch = 0x04,    ///< never set: 0x2103 is not implemented (E28)
  kProgramChecksum = 0x10,  ///< from firmware checking its flash; never simulated (E56)
  kLssParameterChecksum = 0x40,
  kMagneticField = 0x80,  ///< reported with both chip bits: 0x83 (E15)
};

class HallSensors {
 public:
  /// Raw 14-bit reading of chip 1 or 2 (0..16383).
  virtual uint16_t raw(int chip) noexcept {
    (void)chip;
    return 0;
  }
  /// Fault bits the sensor hardware reports (SensorFault).
  virtual uint8_t faults() noexcept { return 0; }

 protected:
  HallSensors() = default;
  ~HallSensors() = default;
  HallSensors(const HallSensors&) = default;
  HallSensors& operator=(const HallSensors&) = default;
  HallSensors(HallSensors&&) = default;
  HallSensors& operator=(HallSensors&&) = default;
};

class SimulatedHallSensors final : public HallSensors {
 public:
  uint16_t raw(int chip) noexcept override { return raw_[chip == 2 ? 1 : 0]; }
  uint8_t faults() noexcept override { return faults_; }

  void setRaw(uint16_t chip1, uint16_t chip2) noexcept {
    raw_[0] = static_cast<uint16_t>(chip1 % 16384U);
    raw_[1] = static_cast<uint16_t>(chip2 % 16384U);
  }
  void setFault(uint8_t bits, bool on) noexcept {
    faults_ = static_cast<uint8_t>(on ? (faults_ | bits) : (faults_ & ~bits));
  }

 private:
  uint16_t raw_[2] = {0, 0};
  uint8_t faults_ = 0;
};

}  // namespace costa::gefran
