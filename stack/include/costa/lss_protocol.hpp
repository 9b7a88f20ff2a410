// LSS protocol constants of CiA 305: command specifiers (byte 0 of every LSS frame), modes,
// error codes and the Fastscan and bit timing table values.
#pragma once

#include <stdint.h>

namespace costa::lss {

// Switch state services.
inline constexpr uint8_t kSwitchStateGlobal = 0x04;
inline constexpr uint8_t kSwitchSelectiveVendor = 0x40;
inline constexpr uint8_t kSwitchSelectiveProduct = 0x41;
inline constexpr uint8_t kSwitchSelectiveRevision = 0x42;
inline constexpr uint8_t kSwitchSelectiveSerial = 0x43;
inline constexpr uint8_t kSwitchSelectiveResponse = 0x44;

// Configuration services.
inline constexpr uint8_t kConfigureNodeId = 0x11;
inline constexpr uint8_t kConfigureBitTiming = 0x13;
inline constexpr uint8_t kActivateBitTiming = 0x15;
inline constexpr uint8_t kStoreConfiguration = 0x17;

// Inquire services.
inline constexpr uint8_t kInquireVendor = 0x5A;
inline constexpr uint8_t kInquireProduct = 0x5B;
inline constexpr uint8_t kInquireRevision = 0x5C;
inline constexpr uint8_t kInquireSerial = 0x5D;
inline constexpr uint8_t kInquireNodeId = 0x5E;

// Identification services.
inline constexpr uint8_t kIdentifyVendor = 0x46;
inline constexpr uint8_t kIdentifyProduct = 0x47;
inline constexpr uint8_t kIdentifyRevisionLow = 0x48;
inline constexpr uint8_t kIdentifyRevisionHigh = 0x49;
inline constexpr uint8_t kIdentifySerialLow = 0x4A;
inline constexpr uint8_t kIdentifySerialHigh = 0x4B;
inline constexpr uint8_t kIdentifyNonConfigured = 0x4C;
inline constexpr uint8_t kIdentifySlave = 0x4F;  ///< Also the answer to Fastscan.
inline constexpr uint8_t kIdentifyNonConfiguredSlave = 0x50;
inline constexpr uint8_t kFastscan = 0x51;

// Switch state global modes.
inline constexpr uint8_t kModeWaiting = 0;
inline constexpr uint8_t kModeConfiguration = 1;

// Error codes (byte 1 of configuration responses).
inline constexpr uint8_t kSuccess = 0;
inline constexpr uint8_t kNodeIdOutOfRange = 1;
inline constexpr uint8_t kBitTimingNotSupported = 1;

// Fastscan.
inline constexpr uint8_t kFastscanConfirm = 0x80;  ///< BitChecked: restart, every slave answers.
inline constexpr uint8_t kFastscanLastBit = 31;    ///< Highest valid BitChecked otherwise.
inline constexpr uint8_t kFastscanSerial = 3;      ///< Highest LSSSub/LSSNext (0 = vendor-id).

// Bit timing tables.
inline constexpr uint8_t kCiaBitTimingTable = 0;
inline constexpr uint8_t kReservedCiaBitTimingIndex = 5;
inline constexpr uint8_t kLastCiaBitTimingIndex = 9;  ///< Automatic bit rate detection.
inline constexpr uint8_t kFirstManufacturerBitTimingTable = 128;

}  // namespace costa::lss
