// Device-specific wire behaviour. A device target selects its behaviour by passing a
// DeviceProfile to its node; the core reads these fields and never tests for a device by name.
// Every field defaults to the CiA 301 behaviour, so `DeviceProfile{}` is a conformant slave.
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

/// Meaning of bits 31 and 30 of a PDO COB-ID (sub-index 1 of 0x1400+/0x1800+).
enum class PdoCobIdPolarity : uint8_t {
  /// CiA 301: bit 31 = 1 means "PDO does not exist / not valid"; bit 30 = 1 means "no RTR
  /// allowed on this PDO".
  kCia301,
  /// The opposite: bit 31 = 1 enables the PDO, bit 30 = 1 allows RTR.
  kBit31EnablesBit30AllowsRtr,
};

/// What TPDO transmission type 0 means.
enum class TpdoType0 : uint8_t {
  /// CiA 301: synchronous acyclic: sent at a SYNC only when the application signalled an event
  /// since the previous SYNC.
  kAcyclicOnEvent,
  /// Sent at every SYNC.
  kEverySync,
};

/// Which TPDO transmission types answer a remote request (when the COB-ID allows RTR).
enum class TpdoRtrTypes : uint8_t {
  /// RTR-only types 252 and 253 and the event-driven types 254 and 255.
  kCia301,
  /// Additionally the synchronous types 0..240.
  kAllTypes,
};

/// Layout of an EMCY frame.
enum class EmcyLayout : uint8_t {
  /// CiA 301: error code (2 bytes, LE), error register, 5 manufacturer-specific bytes.
  kCia301,
  /// Bytes 0..2 zero, the error register in byte 3 (the 4th data byte), bytes 4..7 zero.
  kErrorRegisterInFourthByte,
};

/// An inclusive range of CAN-IDs; {0, 0} means "no device-specific restriction".
struct CanIdRange {
  uint16_t first = 0;
  uint16_t last = 0;
  constexpr bool restricts() const noexcept { return first != 0U || last != 0U; }
  constexpr bool contains(uint32_t id) const noexcept { return id >= first && id <= last; }
};

struct DeviceProfile {
  ExpeditedUploadFormat expeditedUpload = ExpeditedUploadFormat::kSizeIndicated;
  PdoCobIdPolarity pdoCobIdPolarity = PdoCobIdPolarity::kCia301;
  TpdoType0 tpdoType0 = TpdoType0::kAcyclicOnEvent;
  TpdoRtrTypes tpdoRtrTypes = TpdoRtrTypes::kCia301;
  /// CAN-IDs an RPDO/TPDO may be given in addition to CiA 301's restricted-ID rule.
  CanIdRange rpdoCanIds{};
  CanIdRange tpdoCanIds{};
  EmcyLayout emcyLayout = EmcyLayout::kCia301;
  /// Toggle bit of the first node-guarding reply after a reset communication (CiA 301: 0).
  uint8_t guardToggleStart = 0;
  /// The device answers node guarding (a remote request on 0x700 + node-id, CiA 301 7.2.8.3.2.1).
  /// false: a device with heartbeat only; such remote requests are ignored (and counted).
  bool nodeGuarding = true;
  /// Event-driven TPDOs (254/255) are sent once when the node enters OPERATIONAL. CiA 301 does
  /// not ask for it (events and the event timer trigger them), so the default is off.
  bool tpdoOnEnteringOperational = false;
  /// SDO aborts for values out of range: CiA 301's 0x06090031 (too high) / 0x06090032 (too low),
  /// or 0x06090030 (value range exceeded) for both when false.
  bool distinguishHighAndLowValues = true;
  /// An EMCY with error code 0x0000 when the last error condition clears (CiA 301).
  bool emcyOnErrorReset = true;
  /// The error register 0x1001 (and the EMCY's register byte) reflects the active errors. When
  /// false both always read 0 (a device that does not implement the register).
  bool reportErrorRegister = true;
  /// The node reports life-guarding and heartbeat-consumer errors with EMCY 0x8130 itself; when
  /// false only the application events fire and the device reports them its own way.
  bool emcyForErrorControl = true;
};

}  // namespace costa
