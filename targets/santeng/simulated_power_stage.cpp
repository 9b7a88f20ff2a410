#include "simulated_power_stage.hpp"

namespace costa::santeng {

void SimulatedPowerStage::step(const ChannelCommand (&commands)[kChannels],
                               Microseconds elapsed) noexcept {
  for (size_t channel = 0; channel < kChannels; ++channel) {
    channels_[channel].run(commands[channel], elapsed);
  }
}

bool SimulatedPowerStage::atRest(const ChannelCommand (&commands)[kChannels]) const noexcept {
  return channels_[0].atRest(commands[0]) && channels_[1].atRest(commands[1]);
}

void SimulatedPowerStage::read(size_t channel, ChannelReading* reading) const noexcept {
  *reading = channels_[channel].reading();
}

void SimulatedPowerStage::read(ControllerReading* reading) const noexcept {
  ControllerReading out;
  int32_t batteryAmpsTimes10 = 0;
  for (size_t channel = 0; channel < kChannels; ++channel) {
    const ChannelReading& motor = channels_[channel].reading();
    batteryAmpsTimes10 += motor.batteryAmpsTimes10;
    out.temperatures[channel + 1U] = static_cast<int8_t>(
        kAmbientCelsius + (motor.motorAmpsTimes10 < 1000 ? motor.motorAmpsTimes10 / 20 : 50));
  }
  out.temperatures[0] = kMcuCelsius;
  out.voltages[0] = kInternalVoltsTimes10;
  const int32_t sag = batteryAmpsTimes10 / 20;  // 0.05 ohm: V x 10 = A x 10 / 20
  out.voltages[1] =
      static_cast<uint16_t>(sag < kBatteryVoltsTimes10 ? kBatteryVoltsTimes10 - sag : 0);
  out.voltages[2] = kFiveVoltOutputMillivolts;
  out.digitalInputs = inputs_;
  out.digitalOutputs = outputs_;
  out.faults = faults_;
  *reading = out;
}

void SimulatedPowerStage::loadCounter(size_t channel, int32_t count) noexcept {
  channels_[channel].loadCounter(count);
}

void SimulatedPowerStage::reset() noexcept {
  for (SimulatedChannel& channel : channels_) {
    channel.reset();
  }
}

void SimulatedPowerStage::setFault(uint8_t faults, bool on) noexcept {
  faults &= static_cast<uint8_t>(~(kEmergencyStop | kDefaultConfiguration));  // not the hardware's
  faults_ = static_cast<uint8_t>(on ? faults_ | faults : faults_ & ~faults);
}

void SimulatedPowerStage::setStalled(size_t channel, bool stalled) noexcept {
  channels_[channel].setStalled(stalled);
}

void SimulatedPowerStage::setInput(unsigned number, bool high) noexcept {
  const uint32_t bit = uint32_t{1} << (number - 1U);
  inputs_ = high ? inputs_ | bit : inputs_ & ~bit;
}

void SimulatedPowerStage::setOutput(unsigned number, bool high) noexcept {
  const auto bit = static_cast<uint8_t>(1U << (number - 1U));
  outputs_ = static_cast<uint8_t>(high ? outputs_ | bit : outputs_ & ~bit);
}

}  // namespace costa::santeng
