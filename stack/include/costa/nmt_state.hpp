// NMT states of CiA 301, with the values the heartbeat and node guarding frames carry.
#pragma once

#include <stdint.h>

namespace costa {

enum class NmtState : uint8_t {
  kInitialising = 0x00,  ///< Also the value of the boot-up frame.
  kStopped = 0x04,
  kOperational = 0x05,
  kPreOperational = 0x7F,
};

/// NMT commands (byte 0 of a frame on COB-ID 0x000).
enum class NmtCommand : uint8_t {
  kStart = 0x01,
  kStop = 0x02,
  kEnterPreOperational = 0x80,
  kResetNode = 0x81,
  kResetCommunication = 0x82,
};

const char* describe(NmtState state) noexcept;

}  // namespace costa
