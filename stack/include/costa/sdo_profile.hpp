// How a device's SDO server speaks (SdoServer, and the Linux tracer that decodes its frames).
// Every field defaults to CiA 301.
#pragma once

#include <stdint.h>

namespace costa {

/// How an expedited SDO upload response (the server's answer to 0x40) is encoded.
enum class ExpeditedUploadFormat : uint8_t {
  /// CiA 301: size indicated, command 0x4F / 0x4B / 0x47 / 0x43 for 1 / 2 / 3 / 4 bytes.
  kSizeIndicated,
  /// Command 0x42 (expedited, size not indicated) with the value zero-extended to 4 bytes.
  kFourBytesSizeNotIndicated,
};

struct SdoProfile {
  ExpeditedUploadFormat expeditedUpload = ExpeditedUploadFormat::kSizeIndicated;
  /// Aborts for values out of range: CiA 301's 0x06090031 (too high) / 0x06090032 (too low),
  /// or 0x06090030 (value range exceeded) for both when false.
  bool distinguishHighAndLowValues = true;
};

}  // namespace costa
