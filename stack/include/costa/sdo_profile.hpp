// How a device's SDO server speaks (SdoServer, and the Linux tracer that decodes its frames).
// Every field defaults to CiA 301.
#pragma once

#include <stdint.h>

#include "costa/profile_choice.hpp"

namespace costa {

/// How an expedited SDO upload response (the server's answer to 0x40) is encoded.
enum class ExpeditedUploadFormat : uint8_t {
  /// CiA 301: size indicated, command 0x4F / 0x4B / 0x47 / 0x43 for 1 / 2 / 3 / 4 bytes.
  kSizeIndicated,
  /// Command 0x42 (expedited, size not indicated) with the value zero-extended to 4 bytes.
  kFourBytesSizeNotIndicated,
};

struct SdoProfile {
  // Member names, also where COSTA_PROFILE_CHOICE makes the fields constants.
  // NOLINTBEGIN(readability-identifier-naming)
  COSTA_PROFILE_CHOICE ExpeditedUploadFormat expeditedUpload =
      ExpeditedUploadFormat::kSizeIndicated;
  /// Aborts for values out of range: CiA 301's 0x06090031 (too high) / 0x06090032 (too low),
  /// or 0x06090030 (value range exceeded) for both when false.
  COSTA_PROFILE_CHOICE bool distinguishHighAndLowValues = true;
  /// The shortest request (DLC) the server answers; the bytes a shorter frame lacks count as 0,
  /// and every reply has 8 bytes. CiA 301: 8 (shorter frames are ignored). 1..8; 0 acts as 1.
  COSTA_PROFILE_CHOICE uint8_t shortestRequest = 8;
  /// An expedited download with more bytes than its numeric object (0x23 to an INTEGER16)
  /// stores the object's low bytes, then checks its limits. CiA 301: abort 0x06070012.
  COSTA_PROFILE_CHOICE bool expeditedKeepsLowBytes = false;
  /// An initiate download with e = 0 and s = 0 whose byte count n is not 0 (0x24, 0x28, 0x2C)
  /// is an expedited download of 4 - n bytes. CiA 301: n is valid only with e = s = 1, so such
  /// a request starts a segmented download without size indication.
  COSTA_PROFILE_CHOICE bool expeditedByCountAlone = false;
  // NOLINTEND(readability-identifier-naming)
};

}  // namespace costa
