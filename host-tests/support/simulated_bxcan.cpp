#include "simulated_bxcan.hpp"

namespace costa::test {

using namespace port::stm32::bxcan;

SimulatedBxCan::SimulatedBxCan() {
  registers.mcr = kMcrReset;
  registers.msr = kMsrReset;
  registers.tsr = kTsrReset;
  registers.btr = kBtrReset;
  registers.fmr = kFmrReset;
}

void SimulatedBxCan::onWait() {
  samples.push_back(
      Sample{registers.mcr, registers.msr, registers.btr, registers.fmr, registers.fa1r});
  if (dead) {
    return;
  }
  const uint32_t mcrValue = registers.mcr;
  const bool sleep = (mcrValue & mcr::kSleep) != 0;
  const bool init = (mcrValue & mcr::kInrq) != 0 && !sleep;
  const bool leavingInit = !init && (registers.msr & msr::kInak) != 0;
  if (leavingInit && busStuckDominant) {
    return;
  }
  if (delay_ < latency) {
    ++delay_;
    return;
  }
  delay_ = 0;
  uint32_t status = registers.msr & ~(msr::kInak | msr::kSlak);
  if (init) {
    status |= msr::kInak;
  }
  if (sleep) {
    status |= msr::kSlak;
  }
  registers.msr = status;
}

void SimulatedBxCan::receive(uint32_t rir, uint32_t rdtr, uint32_t rdlr, uint32_t rdhr,
                             uint32_t pending) {
  registers.rx[0].rir = rir;
  registers.rx[0].rdtr = rdtr;
  registers.rx[0].rdlr = rdlr;
  registers.rx[0].rdhr = rdhr;
  registers.rf0r = (registers.rf0r & ~rfr::kFmpMask) | (pending & rfr::kFmpMask);
}

}  // namespace costa::test
