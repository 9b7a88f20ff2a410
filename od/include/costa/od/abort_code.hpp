// SDO abort codes of CiA 301 (table "SDO abort codes"). Dictionary accesses report failures
// with these codes, so an error travels unchanged from a hook or a limit check to the wire.
#pragma once

#include <stdint.h>

namespace costa {

enum class AbortCode : uint32_t {
  kNone = 0x00000000U,  ///< Not an abort: success.
  kToggleBit = 0x05030000U,
  kTimeout = 0x05040000U,
  kCommandSpecifier = 0x05040001U,
  kBlockSize = 0x05040002U,
  kSequenceNumber = 0x05040003U,
  kCrc = 0x05040004U,
  kOutOfMemory = 0x05040005U,
  kUnsupportedAccess = 0x06010000U,
  kReadOfWriteOnly = 0x06010001U,
  kWriteOfReadOnly = 0x06010002U,
  kNoObject = 0x06020000U,
  kNotMappable = 0x06040041U,
  kMappingTooLong = 0x06040042U,
  kParameterIncompatible = 0x06040043U,
  kDeviceIncompatible = 0x06040047U,
  kHardwareError = 0x06060000U,
  kLengthMismatch = 0x06070010U,
  kLengthTooHigh = 0x06070012U,
  kLengthTooLow = 0x06070013U,
  kNoSubIndex = 0x06090011U,
  kInvalidValue = 0x06090030U,
  kValueTooHigh = 0x06090031U,
  kValueTooLow = 0x06090032U,
  kMaxBelowMin = 0x06090036U,
  kResourceNotAvailable = 0x060A0023U,
  kGeneral = 0x08000000U,
  kCannotStore = 0x08000020U,
  kCannotStoreLocal = 0x08000021U,
  kCannotStoreState = 0x08000022U,
  kNoDictionary = 0x08000023U,
  kNoData = 0x08000024U,
};

/// Human-readable CiA 301 description of `code` ("" for unknown codes). For traces and tests.
const char* describe(AbortCode code) noexcept;

}  // namespace costa
