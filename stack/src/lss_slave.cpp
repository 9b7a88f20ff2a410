// LSS slave: frame dispatch by LSS state, switch state global, the configuration and inquire
// services, and the bit timing switch. The identification services (switch state selective,
// identify remote slave, Fastscan) are in lss_identification.cpp.
#include "costa/lss_slave.hpp"

#include "costa/lss_protocol.hpp"
#include "costa/od/little_endian.hpp"

namespace costa {
namespace {

// Whether CiA 305 defines `timing` at all (reserved selectors and indices are refused without
// asking the host).
bool definedBitTiming(LssBitTiming timing) {
  if (timing.tableSelector == lss::kCiaBitTimingTable) {
    return timing.tableIndex <= lss::kLastCiaBitTimingIndex &&
           timing.tableIndex != lss::kReservedCiaBitTimingIndex;
  }
  return timing.tableSelector >= lss::kFirstManufacturerBitTimingTable;
}

}  // namespace

LssSlave::LssSlave(TransmitPath& tx, LssSlaveHost& host) noexcept : tx_(tx), host_(host) {}

void LssSlave::reset(const LssIdentity& identity, uint8_t activeNodeId, uint8_t pendingNodeId,
                     LssBitTiming bitTiming) noexcept {
  identity_ = identity;
  activeNodeId_ = activeNodeId;
  pendingNodeId_ = pendingNodeId;
  pendingBitTiming_ = bitTiming;
  state_ = LssState::kWaiting;
  selectiveMatched_ = 0;
  identifyMatched_ = 0;
  fastscanPosition_ = 0;
  switchPhase_ = SwitchPhase::kIdle;
  switchAt_ = kNever;
  resumeAt_ = kNever;
}

bool LssSlave::nonConfigured() const noexcept {
  return activeNodeId_ == cob::kLssUnconfigured && pendingNodeId_ == cob::kLssUnconfigured;
}

bool LssSlave::valid() const noexcept {
  const auto nodeIdOk = [](uint8_t id) {
    return cob::isValidNodeId(id) || id == cob::kLssUnconfigured;
  };
  if ((state_ != LssState::kWaiting && state_ != LssState::kConfiguration) ||
      !nodeIdOk(activeNodeId_) || !nodeIdOk(pendingNodeId_) || selectiveMatched_ > 3U ||
      identifyMatched_ > 5U || fastscanPosition_ > lss::kFastscanSerial) {
    return false;
  }
  switch (switchPhase_) {
    case SwitchPhase::kIdle: return true;
    case SwitchPhase::kBeforeSwitch:  // the resume is one delay after the switch (and may wrap)
      return switchAt_ != kNever && resumeAt_ != kNever && !before(resumeAt_, switchAt_);
    case SwitchPhase::kAfterSwitch: return resumeAt_ != kNever;
  }
  return false;
}

bool LssSlave::onFrame(const CanFrame& frame, Microseconds now) noexcept {
  if (frame.id != cob::kLssFromMaster || frame.extended || frame.rtr || frame.dlc != 8U ||
      transmissionSuspended()) {
    return false;
  }
  const uint8_t* request = frame.data;
  if (request[0] == lss::kSwitchStateGlobal) {
    // Last step of this call: the host may reset this object from within.
    return switchStateGlobal(request[1]);
  }
  if (handleEitherState(request)) {
    return true;
  }
  return state_ == LssState::kWaiting ? handleWaiting(request) : handleConfiguration(request, now);
}

bool LssSlave::handleEitherState(const uint8_t* request) noexcept {
  const uint8_t cs = request[0];
  if (cs >= lss::kIdentifyVendor && cs <= lss::kIdentifySerialHigh) {
    identifyRemoteSlave(cs, loadU32(request + 1));
    return true;
  }
  if (cs == lss::kIdentifyNonConfigured) {
    if (nonConfigured()) {
      respond(lss::kIdentifyNonConfiguredSlave);
    }
    return true;
  }
  return false;
}

bool LssSlave::handleWaiting(const uint8_t* request) noexcept {
  const uint8_t cs = request[0];
  if (cs >= lss::kSwitchSelectiveVendor && cs <= lss::kSwitchSelectiveSerial) {
    switchStateSelective(cs, loadU32(request + 1));
    return true;
  }
  if (cs == lss::kFastscan) {
    return fastscan(request);
  }
  return false;
}

bool LssSlave::handleConfiguration(const uint8_t* request, Microseconds now) noexcept {
  const uint8_t cs = request[0];
  switch (cs) {
    case lss::kConfigureNodeId: configureNodeId(request[1]); return true;
    case lss::kConfigureBitTiming:
      configureBitTiming(LssBitTiming{request[1], request[2]});
      return true;
    case lss::kActivateBitTiming: activateBitTiming(loadU16(request + 1), now); return true;
    case lss::kStoreConfiguration:
      respond(cs,
              static_cast<uint8_t>(host_.storeConfiguration(pendingNodeId_, pendingBitTiming_)));
      return true;
    case lss::kInquireVendor:
    case lss::kInquireProduct:
    case lss::kInquireRevision:
    case lss::kInquireSerial:
      respondValue(cs, identityValue(static_cast<uint8_t>(cs - lss::kInquireVendor)));
      return true;
    case lss::kInquireNodeId: respond(cs, activeNodeId_); return true;
    default: return false;
  }
}

bool LssSlave::switchStateGlobal(uint8_t mode) noexcept {
  if (mode == lss::kModeConfiguration) {
    state_ = LssState::kConfiguration;
    return true;
  }
  if (mode != lss::kModeWaiting) {
    return false;
  }
  const bool leavingConfiguration = state_ == LssState::kConfiguration;
  state_ = LssState::kWaiting;
  selectiveMatched_ = 0;
  if (leavingConfiguration && activeNodeId_ == cob::kLssUnconfigured &&
      cob::isValidNodeId(pendingNodeId_)) {
    host_.requestResetCommunication();
  }
  return true;
}

void LssSlave::configureNodeId(uint8_t nodeId) noexcept {
  if (!cob::isValidNodeId(nodeId) && nodeId != cob::kLssUnconfigured) {
    respond(lss::kConfigureNodeId, lss::kNodeIdOutOfRange);
    return;
  }
  pendingNodeId_ = nodeId;
  respond(lss::kConfigureNodeId, lss::kSuccess);
}

void LssSlave::configureBitTiming(LssBitTiming timing) noexcept {
  if (!definedBitTiming(timing) || !host_.bitTimingSupported(timing)) {
    respond(lss::kConfigureBitTiming, lss::kBitTimingNotSupported);
    return;
  }
  pendingBitTiming_ = timing;
  respond(lss::kConfigureBitTiming, lss::kSuccess);
}

void LssSlave::activateBitTiming(uint16_t delayMs, Microseconds now) noexcept {
  const Microseconds delay = millisecondsToMicroseconds(delayMs);
  switchPhase_ = SwitchPhase::kBeforeSwitch;
  switchAt_ = at(now, delay);
  resumeAt_ = at(switchAt_, delay);
}

void LssSlave::process(Microseconds now) noexcept {
  if (switchPhase_ == SwitchPhase::kBeforeSwitch && reached(now, switchAt_)) {
    switchPhase_ = SwitchPhase::kAfterSwitch;
    host_.activateBitTiming(pendingBitTiming_);
  }
  if (switchPhase_ == SwitchPhase::kAfterSwitch && reached(now, resumeAt_)) {
    switchPhase_ = SwitchPhase::kIdle;
  }
}

Microseconds LssSlave::nextDeadline() const noexcept {
  switch (switchPhase_) {
    case SwitchPhase::kBeforeSwitch: return switchAt_;
    case SwitchPhase::kAfterSwitch: return resumeAt_;
    case SwitchPhase::kIdle: break;
  }
  return kNever;
}

uint32_t LssSlave::identityValue(uint8_t sub) const noexcept {
  switch (sub) {
    case 0: return identity_.vendorId;
    case 1: return identity_.productCode;
    case 2: return identity_.revisionNumber;
    default: return identity_.serialNumber;
  }
}

void LssSlave::respond(uint8_t cs, uint8_t byte1) noexcept {
  const uint8_t data[8] = {cs, byte1};  // the reserved bytes are zero
  tx_.send(cob::kLssToMaster, data, 8);
}

void LssSlave::respondValue(uint8_t cs, uint32_t value) noexcept {
  uint8_t data[8] = {cs};
  storeU32(data + 1, value);
  tx_.send(cob::kLssToMaster, data, 8);
}

}  // namespace costa
