#include "fuzz_events.hpp"

#include <string.h>

namespace costa::fuzz {
namespace {

constexpr uint8_t kNoNodeId = 0xFF;
constexpr uint32_t kStandardIdMask = 0x7FFU;
constexpr uint32_t kExtendedIdMask = 0x1FFFFFFFU;
constexpr uint8_t kLastFrameOp = 0x3F;
constexpr uint8_t kWaitMicroseconds = 0x40;
constexpr uint8_t kWaitMilliseconds = 0x41;
constexpr uint8_t kWaitSeconds = 0x42;
constexpr uint8_t kWaitDeadline = 0x43;
constexpr uint8_t kWaitJustBeforeDeadline = 0x44;
constexpr uint8_t kLastShortWait = 0x7F;
constexpr uint8_t kRefuse = 0x80;
constexpr uint8_t kAccept = 0x81;
constexpr uint8_t kFirstControllerEvent = 0x82;
constexpr uint8_t kLastControllerEvent = 0x86;
constexpr uint8_t kPowerCycle = 0x87;
constexpr uint8_t kStorageCut = 0x88;
constexpr uint8_t kSimulate = 0x89;
constexpr uint8_t kEntryUpload = 0x8B;
constexpr uint8_t kEntryDownload = 0x8C;
constexpr uint8_t kFirstOwnSdo = 0xC0;

uint32_t littleEndian(const uint8_t* bytes, size_t count) {
  uint32_t value = 0;
  for (size_t i = count; i > 0U; --i) {
    value = (value << 8U) | bytes[i - 1U];
  }
  return value;
}

}  // namespace

PowerOnOptions decodeHeader(uint8_t header) noexcept {
  PowerOnOptions options;
  if (header == 0U) {
    return options;
  }
  options.explicitId = true;
  options.nodeId = header <= 127U ? header : kNoNodeId;
  return options;
}

bool EventReader::take(size_t count, const uint8_t** bytes) noexcept {
  if (size_ - position_ < count) {
    position_ = size_;
    return false;
  }
  *bytes = data_ + position_;
  position_ += count;
  return true;
}

bool EventReader::frame(uint8_t op, Event* event) noexcept {
  const bool remote = (op & 0x10U) != 0U;
  const bool extended = (op & 0x20U) != 0U;
  const uint8_t* id = nullptr;
  if (!take(extended ? 4U : 2U, &id)) {
    return false;
  }
  CanFrame frame;
  frame.extended = extended;
  frame.rtr = remote;
  frame.dlc = static_cast<uint8_t>(op & 0x0FU);
  frame.id = littleEndian(id, extended ? 4U : 2U) & (extended ? kExtendedIdMask : kStandardIdMask);
  if (!remote) {
    const size_t count = frame.dlc < 8U ? frame.dlc : 8U;
    const uint8_t* data = nullptr;
    if (!take(count, &data)) {
      return false;
    }
    memcpy(frame.data, data, count);
  }
  event->kind = EventKind::kFrame;
  event->frame = frame;
  return true;
}

bool EventReader::next(Event* event) noexcept {
  const uint8_t* op = nullptr;
  if (!take(1, &op)) {
    return false;
  }
  *event = Event{};
  const uint8_t* payload = nullptr;
  if (*op <= kLastFrameOp) {
    return frame(*op, event);
  }
  if (*op >= kFirstOwnSdo) {
    if (!take(8, &payload)) {
      return false;
    }
    event->kind = EventKind::kOwnSdoRequest;
    event->frame.dlc = 8;
    memcpy(event->frame.data, payload, 8);
    return true;
  }
  switch (*op) {
    case kWaitMicroseconds:
      if (!take(1, &payload)) {
        return false;
      }
      event->kind = EventKind::kWait;
      event->duration = payload[0];
      return true;
    case kWaitMilliseconds:
      if (!take(2, &payload)) {
        return false;
      }
      event->kind = EventKind::kWait;
      event->duration = millisecondsToMicroseconds(littleEndian(payload, 2));
      return true;
    case kWaitSeconds:
      if (!take(1, &payload)) {
        return false;
      }
      event->kind = EventKind::kWait;
      event->duration = millisecondsToMicroseconds(1000U * payload[0]);
      return true;
    case kWaitDeadline:
    case kWaitJustBeforeDeadline:
      event->kind = EventKind::kWaitForDeadline;
      event->duration = *op == kWaitJustBeforeDeadline ? 1U : 0U;
      return true;
    case kRefuse: event->kind = EventKind::kRefuseFrames; return true;
    case kAccept: event->kind = EventKind::kAcceptFrames; return true;
    case kPowerCycle: event->kind = EventKind::kPowerCycle; return true;
    case kStorageCut:
      if (!take(2, &payload)) {
        return false;
      }
      event->kind = EventKind::kStoragePowerCut;
      event->bytes = littleEndian(payload, 2);
      return true;
    case kSimulate:
      if (!take(1, &payload) || !take(payload[0], &event->text)) {
        return false;
      }
      event->kind = EventKind::kSimulate;
      event->textLength = payload[0];
      return true;
    case kEntryUpload:
      if (!take(1, &payload)) {
        return false;
      }
      event->kind = EventKind::kEntryUpload;
      event->code = payload[0];
      return true;
    case kEntryDownload:
      if (!take(5, &payload)) {
        return false;
      }
      event->kind = EventKind::kEntryDownload;
      event->code = payload[0];
      memcpy(event->frame.data, payload + 1, 4);
      return true;
    default: break;
  }
  if (*op > kWaitJustBeforeDeadline && *op <= kLastShortWait) {
    event->kind = EventKind::kWait;
    event->duration = millisecondsToMicroseconds(*op - kWaitJustBeforeDeadline);
    return true;
  }
  if (*op >= kFirstControllerEvent && *op <= kLastControllerEvent) {
    event->kind = EventKind::kControllerEvent;
    event->code = static_cast<uint8_t>(*op - kFirstControllerEvent);
    return true;
  }
  event->kind = EventKind::kNothing;
  return true;
}

}  // namespace costa::fuzz
