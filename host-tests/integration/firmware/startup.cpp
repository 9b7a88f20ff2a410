// The sensor's startup code: vector table, .data and .bss, constructors, then main().
#include <stdint.h>

extern "C" {
// NOLINTBEGIN(cppcoreguidelines-avoid-non-const-global-variables): the linker script's symbols
extern uint32_t _sidata[];
extern uint32_t _sdata[];
extern uint32_t _edata[];
extern uint32_t _sbss[];
extern uint32_t _ebss[];
extern uint32_t _estack[];
using Constructor = void (*)();
extern Constructor _sinit_array[];
extern Constructor _einit_array[];
// NOLINTEND(cppcoreguidelines-avoid-non-const-global-variables)

int main();
// NOLINTNEXTLINE(readability-identifier-naming): CMSIS name, tick_clock.cpp
void SysTick_Handler();
// NOLINTNEXTLINE(readability-identifier-naming): the part's name, main.cpp
void CAN_RX_IRQHandler();

// NOLINTNEXTLINE(readability-identifier-naming): CMSIS name
[[noreturn]] void Reset_Handler() {
  const uint32_t* source = _sidata;
  for (uint32_t* target = _sdata; target < _edata; ++target, ++source) {
    *target = *source;
  }
  for (uint32_t* target = _sbss; target < _ebss; ++target) {
    *target = 0;
  }
  for (Constructor* constructor = _sinit_array; constructor < _einit_array; ++constructor) {
    (*constructor)();
  }
  main();
  for (;;) {
  }
}

// NOLINTNEXTLINE(readability-identifier-naming): CMSIS name
[[noreturn]] void Default_Handler() {
  for (;;) {
  }
}

using Handler = void (*)();

// The Cortex-M system exceptions, then the part's one interrupt that the sensor uses: the CAN
// controller's receive interrupt (IRQ 0 of this part).
__attribute__((section(".isr_vector"), used)) const Handler sensorVectors[17] = {
    // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): the initial stack pointer
    reinterpret_cast<Handler>(_estack),
    Reset_Handler,
    Default_Handler,  // NMI
    Default_Handler,  // HardFault
    Default_Handler,  // MemManage
    Default_Handler,  // BusFault
    Default_Handler,  // UsageFault
    nullptr,
    nullptr,
    nullptr,
    nullptr,
    Default_Handler,  // SVCall
    Default_Handler,  // DebugMonitor
    nullptr,
    Default_Handler,  // PendSV
    SysTick_Handler,
    CAN_RX_IRQHandler,  // IRQ 0
};
}
