#include "gefran_device.hpp"

#include "angle_model.hpp"
#include "costa/od/little_endian.hpp"

namespace costa::gefran {

static_assert(features::kLss,
              "the GRA/GRN set node-id and bit rate by LSS (CiA 305, errata E50): "
              "build with COSTA_FEATURE_LSS=ON");
static_assert(features::kParameterStorage,
              "the GRA/GRN save parameters with 0x1010 and 0x5999:03 (errata E22): build with "
              "COSTA_FEATURE_PARAMETER_STORAGE=ON");
static_assert(features::kQuirkProfiles,
              "the GRA/GRN send their TPDO on entering operational and keep 0x1001 at 0 (errata "
              "E14, E17): build with COSTA_FEATURE_QUIRK_PROFILES=ON");

namespace {

constexpr uint16_t kResolution = 0x2100;
constexpr uint16_t kZeroPoint = 0x2101;
constexpr uint16_t kErrorBehaviour = 0x4000;
constexpr uint16_t kAutoStart = 0x5000;
constexpr uint16_t kLssParameters = 0x5999;
constexpr uint16_t kGenericError = 0x1000;
constexpr uint32_t kSaveSignature = 0x65766173;

/// CiA 305 bit timing table index of a bit rate in kbit/s from the manual's list, -1 if none.
int tableIndexOf(uint32_t kbits) {
  if (kbits > 1000U) {
    return -1;
  }
  const int index = cia305TableIndex(kbits * 1000U);
  return index >= 0 && (kListedBitRates & (1U << static_cast<unsigned>(index))) != 0U ? index : -1;
}

}  // namespace

GefranDevice::GefranDevice(Node& node, const GefranValues& values, HallSensors& sensors) noexcept
    : node_(node),
      values_(values),
      sensors_(sensors),
      attached_(node.attachHook(kResolution, kZeroPoint, *this) &&
                node.attachHook(kLssParameters, kLssParameters, *this) && node.addListener(*this)) {
}

uint32_t GefranDevice::value(uint16_t index, uint8_t sub) const noexcept {
  return node_.dictionary().readUnsigned32(index, sub, 0);
}

void GefranDevice::onResetApplication() noexcept {
  reportedFaults_ = 0;
  inputs_ = AngleInputs{};
}

void GefranDevice::onResetCommunication() noexcept {
  inputs_ = AngleInputs{};  // the communication area's defaults are back: compute again
  // 0x5000 = 1: automatic NMT start after the boot-up (E16, E17).
  node_.setAutomaticStart(value(kAutoStart, 0) == 1U);
}

void GefranDevice::onStoredParametersInvalid(uint8_t group, StoreResult result) noexcept {
  (void)group;
  (void)result;
  storedFaults_ |= kLssParameterChecksum;  // the only parameter checksum bit (E52)
}

void GefranDevice::updateAngles() noexcept {
  // The angles follow from the chips' raw values and the settings: nothing to do while those
  // stay as they were (the outputs are read-only; a reset clears inputs_).
  const AngleInputs inputs{{sensors_.raw(1), sensors_.raw(2)},
                           {values_.resolution[0], values_.resolution[1]},
                           {values_.zeroPoint[0], values_.zeroPoint[1]},
                           {values_.clockwise[0], values_.clockwise[1]},
                           *values_.littleEndian,
                           true};
  if (inputs == inputs_) {
    return;
  }
  inputs_ = inputs;
  uint16_t angles[2] = {};
  for (size_t chip = 0; chip < 2U; ++chip) {
    const uint16_t raw = inputs.raw[chip];
    AngleSettings settings;
    settings.resolution = inputs.resolution[chip];
    settings.zeroPoint = inputs.zeroPoint[chip];
    settings.clockwise = inputs.clockwise[chip] == 1U;
    angles[chip] = static_cast<uint16_t>(outputAngle(raw, settings));
    values_.rawValues[chip] = raw;
    values_.processData[chip] = angles[chip];
  }
  *values_.processDataBoth = angles[0] | (static_cast<uint32_t>(angles[1]) << 16U);
  packAngles(angles[0], angles[1], inputs.littleEndian == 1U, values_.outputBytes);
}

void GefranDevice::updateErrors() noexcept {
  auto faults = static_cast<uint8_t>(sensors_.faults() | storedFaults_);
  if ((faults & kMagneticField) != 0U) {
    faults |= kChip1Error | kChip2Error;  // 0x83 (E15)
  }
  *values_.errorCode = faults;
  if (faults == reportedFaults_) {
    return;
  }
  // One EMCY per error event: 0x1000, register 0 (E14), 0x4001, 0x00, FF FF FF (lines 270-276);
  // the error reset (CiA 301) when the last error is gone (E45).
  const uint8_t manufacturer[5] = {faults, 0x00, 0xFF, 0xFF, 0xFF};
  const auto added = static_cast<uint8_t>(faults & ~reportedFaults_);
  if (faults == 0U) {
    node_.clearError(kGenericError);
  } else if (reportedFaults_ == 0U) {
    node_.raiseError(kGenericError, kErrorGeneric, manufacturer);
  } else if (added != 0U) {
    node_.signalError(kGenericError, kErrorGeneric, manufacturer);
  }
  reportedFaults_ = faults;
  if (added != 0U) {
    // 0x4000 as 0x1029 (E29): the EMCY leaves first, then 0 pre-operational, 2 stopped.
    node_.errorControl().applyErrorBehaviour(static_cast<uint8_t>(value(kErrorBehaviour, 0)));
  }
}

Microseconds GefranDevice::process(Microseconds now) noexcept {
  (void)now;
  updateAngles();
  updateErrors();
  return kNever;
}

AbortCode GefranDevice::prepareRead(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                                    const ReadRequest& request) noexcept {
  (void)request;
  if (ref.index() == kLssParameters && ref.subIndex() == 1U) {
    dictionary.storeUnsigned(ref, bitRateOf(node_.pendingBitTiming()) / 1000U);
  } else if (ref.index() == kLssParameters && ref.subIndex() == 2U) {
    dictionary.storeUnsigned(ref, node_.pendingNodeId());
  }
  return AbortCode::kNone;
}

AbortCode GefranDevice::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                              const uint8_t* data, size_t length) noexcept {
  const AbortCode checked = dictionary.check(ref, data, length);
  if (checked != AbortCode::kNone) {
    return ref.index() == kLssParameters && ref.subIndex() == 3U ? AbortCode::kCannotStore
                                                                 : checked;
  }
  const auto number = static_cast<uint32_t>(loadLittleEndian(data, length < 4U ? length : 4U));
  if (ref.index() == kResolution && fullScale(static_cast<uint16_t>(number)) == 0U) {
    return AbortCode::kInvalidValue;  // only 1000, 100 and 22 (E26)
  }
  if (ref.index() == kZeroPoint &&
      number >= fullScale(static_cast<uint16_t>(value(kResolution, ref.subIndex())))) {
    return AbortCode::kValueTooHigh;  // beyond a turn at the present resolution (E4)
  }
  if (ref.index() == kLssParameters) {
    switch (ref.subIndex()) {
      case 1: {
        const int index = tableIndexOf(number);
        if (index < 0) {
          return AbortCode::kInvalidValue;  // not one of the listed bit rates (E26)
        }
        node_.setPendingBitTiming(LssBitTiming{0, static_cast<uint8_t>(index)});
        break;
      }
      case 2: node_.setPendingNodeId(static_cast<uint8_t>(number)); break;
      case 3:
        if (number != kSaveSignature) {
          return AbortCode::kCannotStore;  // E51
        }
        return node_.storeLssConfiguration(node_.pendingNodeId(), node_.pendingBitTiming()) ==
                       LssStoreResult::kStored
                   ? AbortCode::kNone
                   : AbortCode::kCannotStore;
      default: break;
    }
  }
  return dictionary.write(ref, data, length);
}

}  // namespace costa::gefran
