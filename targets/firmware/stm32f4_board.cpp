#include "stm32f4_board.hpp"

#include <stdint.h>

namespace costa::firmware::stm32f4 {
namespace {

// RM0090 memory map and RCC/GPIO registers.
constexpr uintptr_t kRcc = 0x40023800U;
constexpr uintptr_t kRccAhb1Enable = kRcc + 0x30U;  // RCC_AHB1ENR
constexpr uintptr_t kRccApb1Enable = kRcc + 0x40U;  // RCC_APB1ENR
constexpr uint32_t kGpioBEnable = 1U << 1;          // GPIOBEN
constexpr uint32_t kGpioDEnable = 1U << 3;          // GPIODEN
constexpr uint32_t kCan1Enable = 1U << 25;          // CAN1EN

constexpr uintptr_t kGpioB = 0x40020400U;
constexpr uintptr_t kGpioMode = kGpioB + 0x00U;           // GPIOx_MODER: 2 bits per pin
constexpr uintptr_t kGpioPull = kGpioB + 0x0CU;           // GPIOx_PUPDR: 2 bits per pin
constexpr uintptr_t kGpioAlternateHigh = kGpioB + 0x24U;  // GPIOx_AFRH: 4 bits per pin 8..15
constexpr uintptr_t kGpioD = 0x40020C00U;
constexpr uintptr_t kGpioDMode = kGpioD + 0x00U;      // GPIOx_MODER
constexpr uintptr_t kGpioDSetReset = kGpioD + 0x18U;  // GPIOx_BSRR: set bits 0..15, reset 16..31
constexpr uint32_t kModeOutput = 1U;
constexpr uint32_t kModeAlternate = 2U;
constexpr uint32_t kPullUp = 1U;
constexpr uint32_t kAlternateCan1 = 9U;  // AF9
constexpr uint32_t kRxPin = 8;
constexpr uint32_t kTxPin = 9;
constexpr uint32_t kRunLedPin = 12;    // PD12, green
constexpr uint32_t kErrorLedPin = 14;  // PD14, red

volatile uint32_t& reg(uintptr_t address) {
  return *reinterpret_cast<volatile uint32_t*>(address);
}

void setField(uintptr_t address, uint32_t shift, uint32_t width, uint32_t value) {
  const uint32_t mask = ((1U << width) - 1U) << shift;
  reg(address) = (reg(address) & ~mask) | ((value << shift) & mask);
}

// Alternate function first, then the mode: the pin never drives anything but CAN1.
void giveToCan1(uint32_t pin) {
  setField(kGpioAlternateHigh, 4U * (pin - 8U), 4, kAlternateCan1);
  setField(kGpioMode, 2U * pin, 2, kModeAlternate);
}

}  // namespace

void connectCan1ToPb8Pb9() noexcept {
  reg(kRccAhb1Enable) = reg(kRccAhb1Enable) | kGpioBEnable;
  reg(kRccApb1Enable) = reg(kRccApb1Enable) | kCan1Enable;
  // Read back: a short delay between enabling a clock and using the peripheral, as the
  // STM32F4 errata sheet asks.
  const uint32_t enabled = reg(kRccApb1Enable);
  (void)enabled;
  giveToCan1(kRxPin);
  giveToCan1(kTxPin);
  setField(kGpioPull, 2U * kRxPin, 2, kPullUp);
}

namespace {

// One write to BSRR: no read-modify-write of the port, so no other pin can be disturbed.
void drive(uint32_t pin, bool high) {
  reg(kGpioDSetReset) = high ? 1U << pin : 1U << (pin + 16U);
}

}  // namespace

void BoardLeds::connect() noexcept {
  reg(kRccAhb1Enable) = reg(kRccAhb1Enable) | kGpioDEnable;
  const uint32_t enabled = reg(kRccAhb1Enable);  // read back, as above
  (void)enabled;
  drive(kRunLedPin, false);
  drive(kErrorLedPin, false);
  setField(kGpioDMode, 2U * kRunLedPin, 2, kModeOutput);
  setField(kGpioDMode, 2U * kErrorLedPin, 2, kModeOutput);
}

void BoardLeds::setRun(bool on) noexcept {
  drive(kRunLedPin, on);
}

void BoardLeds::setError(bool on) noexcept {
  drive(kErrorLedPin, on);
}

}  // namespace costa::firmware::stm32f4
