// LSS slave: the services that pick devices by their identity — switch state selective,
// identify remote slave and LSS Fastscan.
#include "costa/lss_protocol.hpp"
#include "costa/lss_slave.hpp"
#include "costa/od/little_endian.hpp"

namespace costa {

void LssSlave::switchStateSelective(uint8_t cs, uint32_t value) noexcept {
  // Frame k of the sequence (k = cs - 0x40) carries identity value k; it counts only when the
  // k frames before it have matched.
  const auto position = static_cast<uint8_t>(cs - lss::kSwitchSelectiveVendor);
  const bool expected = position == 0U || position == selectiveMatched_;
  if (!expected || value != identityValue(position)) {
    selectiveMatched_ = 0;
    return;
  }
  selectiveMatched_ = static_cast<uint8_t>(position + 1U);
  if (cs == lss::kSwitchSelectiveSerial) {
    selectiveMatched_ = 0;
    state_ = LssState::kConfiguration;
    respond(lss::kSwitchSelectiveResponse);
  }
}

void LssSlave::identifyRemoteSlave(uint8_t cs, uint32_t value) noexcept {
  const auto position = static_cast<uint8_t>(cs - lss::kIdentifyVendor);
  bool matches = false;
  switch (cs) {
    case lss::kIdentifyVendor: matches = value == identity_.vendorId; break;
    case lss::kIdentifyProduct: matches = value == identity_.productCode; break;
    case lss::kIdentifyRevisionLow: matches = value <= identity_.revisionNumber; break;
    case lss::kIdentifyRevisionHigh: matches = value >= identity_.revisionNumber; break;
    case lss::kIdentifySerialLow: matches = value <= identity_.serialNumber; break;
    default: matches = value >= identity_.serialNumber; break;
  }
  const bool expected = position == 0U || position == identifyMatched_;
  if (!expected || !matches) {
    identifyMatched_ = 0;
    return;
  }
  identifyMatched_ = static_cast<uint8_t>(position + 1U);
  if (cs == lss::kIdentifySerialHigh) {
    identifyMatched_ = 0;
    respond(lss::kIdentifySlave);
  }
}

bool LssSlave::fastscan(const uint8_t* request) noexcept {
  const uint32_t idNumber = loadU32(request + 1);
  const uint8_t bitChecked = request[5];
  const uint8_t lssSub = request[6];
  const uint8_t lssNext = request[7];
  if (bitChecked == lss::kFastscanConfirm) {
    if (nonConfigured()) {
      fastscanPosition_ = 0;
      respond(lss::kIdentifySlave);
    }
    return true;
  }
  if (bitChecked > lss::kFastscanLastBit || lssSub > lss::kFastscanSerial ||
      lssNext > lss::kFastscanSerial) {
    return false;
  }
  if (!nonConfigured() || lssSub != fastscanPosition_) {
    return true;
  }
  const uint32_t checkedBits = UINT32_MAX << bitChecked;  // bits 31..BitChecked
  if (((idNumber ^ identityValue(lssSub)) & checkedBits) != 0U) {
    return true;
  }
  fastscanPosition_ = lssNext;
  if (bitChecked == 0U && lssNext < lssSub) {
    state_ = LssState::kConfiguration;
  }
  respond(lss::kIdentifySlave);
  return true;
}

}  // namespace costa
