// The simulated power stage of a Santeng controller: two SimulatedChannel motors, the
// controller's voltages and temperatures, and what a test bench changes (simulation commands:
// faults, a stalled motor, digital inputs and outputs). Deterministic, freestanding.
//
// Readings (errata B11, B12): internal 13.5 V and 5 V output 4730 mV fixed, battery 24.6 V less
// 0.05 ohm times the current drawn (135, 246, 4730 at rest, line 660); MCU at 30 degrees C, the
// channel sides at 25 degrees C plus 0.5 degrees per ampere of their motor.
#pragma once

#include "power_stage.hpp"
#include "simulated_channel.hpp"

namespace costa::santeng {

class SimulatedPowerStage final : public PowerStage {
 public:
  static constexpr uint16_t kInternalVoltsTimes10 = 135;
  static constexpr uint16_t kBatteryVoltsTimes10 = 246;
  static constexpr uint16_t kFiveVoltOutputMillivolts = 4730;
  static constexpr int8_t kMcuCelsius = 30;
  static constexpr int8_t kAmbientCelsius = 25;

  void step(const ChannelCommand (&commands)[kChannels], Microseconds elapsed) noexcept override;
  bool atRest(const ChannelCommand (&commands)[kChannels]) const noexcept override;
  void read(size_t channel, ChannelReading* reading) const noexcept override;
  void read(ControllerReading* reading) const noexcept override;
  void loadCounter(size_t channel, int32_t count) noexcept override;
  void reset() noexcept override;

  // What the simulation commands change (santeng_control.hpp).
  /// Raises or clears fault flags the hardware would detect.
  void setFault(uint8_t faults, bool on) noexcept;
  /// A blocked motor: it does not turn whatever its command.
  void setStalled(size_t channel, bool stalled) noexcept;
  /// Digital input (1..32) or output (1..8) `number` high or low.
  void setInput(unsigned number, bool high) noexcept;
  void setOutput(unsigned number, bool high) noexcept;

 private:
  SimulatedChannel channels_[kChannels];
  uint8_t faults_ = 0;
  uint32_t inputs_ = 0;
  uint8_t outputs_ = 0;
};

}  // namespace costa::santeng
