// Device-specific wire behaviour. A device target selects its behaviour by passing a
// DeviceProfile to its node; the core reads these fields and never tests for a device by name.
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

/// Every field defaults to the CiA 301 behaviour, so `DeviceProfile{}` is a conformant slave.
struct DeviceProfile {
  ExpeditedUploadFormat expeditedUpload = ExpeditedUploadFormat::kSizeIndicated;
};

}  // namespace costa
