#include "costa/od/abort_code.hpp"

namespace costa {

const char* describe(AbortCode code) noexcept {
  switch (code) {
    case AbortCode::kNone: return "no error";
    case AbortCode::kToggleBit: return "toggle bit not alternated";
    case AbortCode::kTimeout: return "SDO protocol timed out";
    case AbortCode::kCommandSpecifier: return "command specifier not valid or unknown";
    case AbortCode::kBlockSize: return "invalid block size";
    case AbortCode::kSequenceNumber: return "invalid sequence number";
    case AbortCode::kCrc: return "CRC error";
    case AbortCode::kOutOfMemory: return "out of memory";
    case AbortCode::kUnsupportedAccess: return "unsupported access to an object";
    case AbortCode::kReadOfWriteOnly: return "attempt to read a write only object";
    case AbortCode::kWriteOfReadOnly: return "attempt to write a read only object";
    case AbortCode::kNoObject: return "object does not exist";
    case AbortCode::kNotMappable: return "object cannot be mapped to the PDO";
    case AbortCode::kMappingTooLong: return "mapped objects exceed the PDO length";
    case AbortCode::kParameterIncompatible: return "general parameter incompatibility";
    case AbortCode::kDeviceIncompatible: return "general internal incompatibility in the device";
    case AbortCode::kHardwareError: return "access failed due to a hardware error";
    case AbortCode::kLengthMismatch: return "data type does not match, length does not match";
    case AbortCode::kLengthTooHigh: return "data type does not match, length too high";
    case AbortCode::kLengthTooLow: return "data type does not match, length too low";
    case AbortCode::kNoSubIndex: return "sub-index does not exist";
    case AbortCode::kInvalidValue: return "invalid value for parameter";
    case AbortCode::kValueTooHigh: return "value of parameter written too high";
    case AbortCode::kValueTooLow: return "value of parameter written too low";
    case AbortCode::kMaxBelowMin: return "maximum value is less than minimum value";
    case AbortCode::kResourceNotAvailable: return "resource not available";
    case AbortCode::kGeneral: return "general error";
    case AbortCode::kCannotStore: return "data cannot be transferred or stored to the application";
    case AbortCode::kCannotStoreLocal:
      return "data cannot be transferred or stored because of local control";
    case AbortCode::kCannotStoreState:
      return "data cannot be transferred or stored because of the present device state";
    case AbortCode::kNoDictionary: return "object dictionary not present";
    case AbortCode::kNoData: return "no data available";
  }
  return "";
}

}  // namespace costa
