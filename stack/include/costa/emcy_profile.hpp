// How a device's EMCY producer encodes its frames and its error register (EmcyProducer, and the
// Linux tracer). Every field defaults to CiA 301.
#pragma once

#include <stdint.h>

#include "costa/profile_choice.hpp"

namespace costa {

/// Layout of an EMCY frame.
enum class EmcyLayout : uint8_t {
  /// CiA 301: error code (2 bytes, LE), error register, 5 manufacturer-specific bytes.
  kCia301,
  /// Bytes 0..2 zero, the error register in byte 3 (the 4th data byte), bytes 4..7 zero.
  kErrorRegisterInFourthByte,
};

struct EmcyProfile {
  // Member names, also where COSTA_PROFILE_CHOICE makes the fields constants.
  // NOLINTBEGIN(readability-identifier-naming)
  COSTA_PROFILE_CHOICE EmcyLayout layout = EmcyLayout::kCia301;
  /// An EMCY with error code 0x0000 when the last error condition clears (CiA 301).
  COSTA_PROFILE_CHOICE bool errorResetFrame = true;
  /// The error register 0x1001 (and the EMCY's register byte) reflects the active errors. When
  /// false both always read 0 (a device that does not implement the register).
  COSTA_PROFILE_CHOICE bool reportErrorRegister = true;
  /// The device sends EMCY frames (CiA 301). When false (a device without an EMCY producer),
  /// error conditions and events still set the error register 0x1001 and the history 0x1003,
  /// and nothing is sent.
  COSTA_PROFILE_CHOICE bool sendFrames = true;
  // NOLINTEND(readability-identifier-naming)
};

}  // namespace costa
