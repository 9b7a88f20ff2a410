// A bxCAN register block in RAM that plays the controller's part where the driver waits for it.
//
// Registers are plain memory: what the driver writes stays there for the test to read, and the
// test sets what the hardware would report (TSR, RF0R, the FIFO mailbox, ESR). Mode changes are
// the one thing the hardware does on its own while the driver watches, so the driver's wait
// hook calls onWait(), which answers MCR's requests in MSR the way RM0090 describes.
#pragma once

#include <stdint.h>

#include <vector>

#include "costa/port/stm32/bxcan_port.hpp"
#include "costa/port/stm32/bxcan_registers.hpp"

namespace costa::test {

class SimulatedBxCan {
 public:
  /// Register values after reset (RM0090).
  static constexpr uint32_t kMcrReset = 0x00010002;  // DBF, SLEEP
  static constexpr uint32_t kMsrReset = 0x00000C02;  // RX, SAMP, SLAK
  static constexpr uint32_t kTsrReset = 0x1C000000;  // all mailboxes empty
  static constexpr uint32_t kBtrReset = 0x01230000;
  static constexpr uint32_t kFmrReset = 0x2A1C0E01;  // CAN2SB = 14, FINIT

  /// What the registers looked like at one status read of a wait.
  struct Sample {
    uint32_t mcr;
    uint32_t msr;
    uint32_t btr;
    uint32_t fmr;
    uint32_t fa1r;
  };

  SimulatedBxCan();
  SimulatedBxCan(const SimulatedBxCan&) = delete;
  SimulatedBxCan& operator=(const SimulatedBxCan&) = delete;

  /// Connects `port`'s wait hook to this simulation.
  void attach(port::stm32::BxCanPort& port) { port.setWaitHook(&SimulatedBxCan::hook, this); }

  /// One status read of a wait: MSR follows MCR (after `latency` further reads), unless the
  /// controller is dead (no acknowledge at all) or the bus is stuck dominant (initialisation is
  /// never left).
  void onWait();

  /// Puts a message in FIFO 0's output mailbox, `pending` messages in the FIFO (1..3).
  void receive(uint32_t rir, uint32_t rdtr, uint32_t rdlr, uint32_t rdhr, uint32_t pending = 1);

  port::stm32::BxCanRegisters registers{};
  bool dead = false;
  bool busStuckDominant = false;
  uint32_t latency = 0;
  std::vector<Sample> samples;

 private:
  static void hook(void* self) { static_cast<SimulatedBxCan*>(self)->onWait(); }
  uint32_t delay_ = 0;
};

}  // namespace costa::test
