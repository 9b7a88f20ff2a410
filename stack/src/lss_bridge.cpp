#include "costa/lss_bridge.hpp"

#include "costa/nmt_state_machine.hpp"

namespace costa {

bool LssBridge::bitTimingSupported(LssBitTiming timing) noexcept {
  return timing.tableSelector == 0U && timing.tableIndex < 16U &&
         (nmt_.services().settings.lssBitRates & (1U << timing.tableIndex)) != 0U;
}

void LssBridge::activateBitTiming(LssBitTiming timing) noexcept {
  const NmtStateMachine::Services& services = nmt_.services();
  services.bitTiming.switchTo(timing, services.settings.manufacturerBitRates);
  services.bitTiming.setPending(timing);
  services.listeners.notify(
      [timing](NodeEvents& listener) { listener.onBitTimingActivation(timing); });
}

LssStoreResult LssBridge::storeConfiguration(uint8_t nodeId, LssBitTiming timing) noexcept {
  return nmt_.services().stored.storeLssConfiguration(nodeId, timing);
}

void LssBridge::requestResetCommunication() noexcept {
  nmt_.resetCommunication();
}

}  // namespace costa
