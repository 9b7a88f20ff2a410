#include "costa/lss_bridge.hpp"

#include "costa/nmt_state_machine.hpp"

namespace costa {

bool LssBridge::bitTimingSupported(LssBitTiming timing) noexcept {
  return timing.tableSelector == 0U && timing.tableIndex < 16U &&
         (settings_.lssBitRates & (1U << timing.tableIndex)) != 0U;
}

void LssBridge::activateBitTiming(LssBitTiming timing) noexcept {
  bitTiming_.switchTo(timing, settings_.manufacturerBitRates);
  bitTiming_.setPending(timing);
  listeners_.notify([timing](NodeEvents& listener) { listener.onBitTimingActivation(timing); });
}

LssStoreResult LssBridge::storeConfiguration(uint8_t nodeId, LssBitTiming timing) noexcept {
  return stored_.storeLssConfiguration(nodeId, timing);
}

void LssBridge::requestResetCommunication() noexcept {
  nmt_.resetCommunication();
}

}  // namespace costa
