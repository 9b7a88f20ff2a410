// The board under the STM32F4 example image: the part of the set-up that the bxCAN driver
// leaves to the integrator, for one assumed board.
//
// Assumptions: the clock tree as after reset (HSI, 16 MHz for the core, AHB and APB1; no PLL),
// and CAN1 on PB8 (CAN1_RX) and PB9 (CAN1_TX), alternate function 9, wired to a transceiver.
// A real board changes these lines, not the driver.
#pragma once

#include <stdint.h>

namespace costa::firmware::stm32f4 {

inline constexpr uint32_t kCoreClockHz = 16000000;
inline constexpr uint32_t kApb1ClockHz = 16000000;

/// Clocks GPIOB and CAN1 and hands PB8/PB9 to CAN1 (pull-up on the receive pin, so that an
/// unconnected transceiver reads recessive).
void connectCan1ToPb8Pb9() noexcept;

}  // namespace costa::firmware::stm32f4
