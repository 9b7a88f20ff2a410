// The board under the STM32F4 example image: the part of the set-up that the bxCAN driver
// leaves to the integrator, for one assumed board.
//
// Assumptions: the clock tree as after reset (HSI, 16 MHz for the core, AHB and APB1; no PLL),
// CAN1 on PB8 (CAN1_RX) and PB9 (CAN1_TX), alternate function 9, wired to a transceiver; the
// CiA 303-3 LEDs on PD12 (green, RUN) and PD14 (red, ERROR), lit by a high output, as on the
// STM32F4-Discovery board. A real board changes these lines, not the driver.
#pragma once

#include <stdint.h>

#include "costa/port/indicator_outputs.hpp"

namespace costa::firmware::stm32f4 {

inline constexpr uint32_t kCoreClockHz = 16000000;
inline constexpr uint32_t kApb1ClockHz = 16000000;

/// Clocks GPIOB and CAN1 and hands PB8/PB9 to CAN1 (pull-up on the receive pin, so that an
/// unconnected transceiver reads recessive).
void connectCan1ToPb8Pb9() noexcept;

/// The RUN and ERROR LEDs on PD12 and PD14: the constructor changes nothing (static storage),
/// connect() clocks GPIOD and makes both pins outputs, off.
class BoardLeds final : public IndicatorOutputs {
 public:
  void connect() noexcept;
  void setRun(bool on) noexcept override;
  void setError(bool on) noexcept override;
};

}  // namespace costa::firmware::stm32f4
