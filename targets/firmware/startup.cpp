// Minimal Cortex-M startup: vector table, .data/.bss initialisation, constructors, main().
// No C library start files are used (-nostartfiles).
#include <stdint.h>

extern "C" {
extern uint32_t __data_start[];
extern uint32_t __data_end[];
extern uint32_t __data_load[];
extern uint32_t __bss_start[];
extern uint32_t __bss_end[];
extern uint32_t __stack_top[];
using Constructor = void (*)();
extern Constructor __init_array_start[];
extern Constructor __init_array_end[];

int main();

[[noreturn]] void costa_reset_handler() {
#if defined(__ARM_FP)
  // Hard-float builds (Cortex-M4F): the FPU is off after reset and its first instruction would
  // fault. CPACR (0xE000ED88) bits 20..23: full access to CP10 and CP11.
  volatile uint32_t* const cpacr = reinterpret_cast<volatile uint32_t*>(0xE000ED88U);
  *cpacr = *cpacr | (0xFU << 20U);
  asm volatile("dsb\n\tisb" ::: "memory");
#endif
  const uint32_t* source = __data_load;
  for (uint32_t* target = __data_start; target < __data_end; ++target, ++source) {
    *target = *source;
  }
  for (uint32_t* target = __bss_start; target < __bss_end; ++target) {
    *target = 0;
  }
  for (Constructor* constructor = __init_array_start; constructor < __init_array_end;
       ++constructor) {
    (*constructor)();
  }
  main();
  for (;;) {
  }
}

[[noreturn]] void costa_default_handler() {
  for (;;) {
  }
}

// An image that uses SysTick defines this handler; otherwise SysTick lands in the default one.
__attribute__((weak)) void costa_systick_handler() {
  costa_default_handler();
}

using Handler = void (*)();

// Initial stack pointer, reset, and the Cortex-M system exceptions.
__attribute__((section(".vectors"), used)) const Handler costaVectorTable[16] = {
    reinterpret_cast<Handler>(__stack_top),
    costa_reset_handler,
    costa_default_handler,  // NMI
    costa_default_handler,  // HardFault
    costa_default_handler,  // MemManage
    costa_default_handler,  // BusFault
    costa_default_handler,  // UsageFault
    nullptr,
    nullptr,
    nullptr,
    nullptr,
    costa_default_handler,  // SVCall
    costa_default_handler,  // DebugMonitor
    nullptr,
    costa_default_handler,  // PendSV
    costa_systick_handler,  // SysTick
};
}
