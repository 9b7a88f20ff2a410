// The fuzz input encoding: a header byte, then a sequence of events (frames from the bus, time
// passing, CAN controller conditions, power cycles, storage power loss, simulation commands).
// docs/fuzzing.md has the same table with examples.
//
// Header (byte 0; an empty input powers the device on and stops):
//   0          the device's own node-id (a stored LSS node-id wins), as `costa-slave DEVICE`
//   1..127     this node-id, given explicitly, as `costa-slave --node-id N DEVICE`
//   128..255   no node-id (255): the node waits for LSS, as `costa-slave --node-id 255 DEVICE`
//
// Events (first byte, then its payload; multi-byte numbers little-endian):
//   0x00-0x0F  data frame, 11-bit id, DLC = low nibble    id (2 bytes, & 0x7FF), min(DLC, 8) bytes
//   0x10-0x1F  remote frame (RTR), 11-bit id, DLC = low   id (2 bytes, & 0x7FF)
//   0x20-0x2F  data frame, 29-bit id, DLC = low nibble    id (4 bytes, & 0x1FFFFFFF), data bytes
//   0x30-0x3F  remote frame, 29-bit id, DLC = low nibble  id (4 bytes, & 0x1FFFFFFF)
//   0x40       wait N microseconds                        N (1 byte)
//   0x41       wait N milliseconds                        N (2 bytes)
//   0x42       wait N seconds                             N (1 byte)
//   0x43       wait until the deadline process() returned
//   0x44       wait until 1 us before that deadline
//   0x45-0x7F  wait 1..59 milliseconds (byte - 0x44)
//   0x80       the CAN controller refuses every frame (transmit mailboxes full)
//   0x81       the controller takes frames again (the driver calls flushTx())
//   0x82-0x86  controller event: rx overrun, error passive, error active, bus-off, recovered
//   0x87       power cycle: the device restarts over the same non-volatile storage
//   0x88       the storage loses power after N more bytes are programmed or erased; the
//              device then restarts at the end of the event (a power cut)  N (2 bytes)
//   0x89       a simulation command: the device's control() (targets/device_control.hpp), as a
//              transcript's `sim` line; refused ones change nothing   N (1 byte), N text bytes
//   0x8A       nothing (skipped)
//   0x8B       SDO upload of dictionary entry K (entries in dictionary order, K modulo their
//              number) from the node's own server                  K (1 byte)
//   0x8C       SDO expedited download of entry K with the size of its value (4 bytes for
//              other sizes) to the node's own server         K (1 byte), value (4 bytes)
//   0x8D-0xBF  nothing (skipped)
//   0xC0-0xFF  SDO request to the node's own server: DLC 8 on 0x600 + current node-id  8 bytes
// An event whose payload is cut short ends the input, and so does the event during which
// process() has been called 100000 times (fuzz_session.hpp).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/port/can_frame.hpp"
#include "costa/time.hpp"

namespace costa::fuzz {

/// Node-id choice of the header byte.
struct PowerOnOptions {
  uint8_t nodeId = 0;       ///< 0: the device's own; 1..127; 0xFF: none (LSS only)
  bool explicitId = false;  ///< given on the command line (a stored LSS node-id does not win)
};

PowerOnOptions decodeHeader(uint8_t header) noexcept;

enum class EventKind : uint8_t {
  kFrame,            ///< `frame` from the bus
  kOwnSdoRequest,    ///< `frame.data` to 0x600 + the node-id at the time (id filled in later)
  kWait,             ///< `duration` microseconds pass
  kWaitForDeadline,  ///< until the deadline, minus `duration` (0 or 1) microseconds
  kRefuseFrames,
  kAcceptFrames,
  kControllerEvent,  ///< `code`: 0..4 = CanControllerEvent in declaration order
  kPowerCycle,
  kStoragePowerCut,  ///< after `bytes` bytes
  kSimulate,         ///< the command `text` (`textLength` bytes, not NUL-terminated)
  kEntryUpload,      ///< of entry `code`
  kEntryDownload,    ///< of `frame.data[0..3]` to entry `code`
  kNothing,
};

struct Event {
  EventKind kind = EventKind::kNothing;
  CanFrame frame;
  Microseconds duration = 0;
  size_t bytes = 0;
  const uint8_t* text = nullptr;  ///< inside the input
  size_t textLength = 0;
  uint8_t code = 0;
};

/// Reads events from a fuzz input, after its header byte.
class EventReader {
 public:
  EventReader(const uint8_t* data, size_t size) noexcept
      : data_(data), size_(size), position_(size > 0U ? 1U : 0U) {}

  /// The header byte (0 when the input is empty).
  uint8_t header() const noexcept { return size_ > 0U ? data_[0] : 0U; }
  /// Decodes the next event; false at the end of the input or when its payload is cut short.
  bool next(Event* event) noexcept;

 private:
  bool take(size_t count, const uint8_t** bytes) noexcept;
  bool frame(uint8_t op, Event* event) noexcept;

  const uint8_t* data_;
  size_t size_;
  size_t position_;  ///< of the next byte to read (the header is byte 0)
};

}  // namespace costa::fuzz
