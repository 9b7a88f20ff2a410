#include "example_device.hpp"

#include <string.h>

namespace costa::example {
namespace {
constexpr Microseconds kSecond = 1000000;
constexpr uint8_t kRestartUptime = 1;
constexpr uint8_t kSelfTest = 3;
}  // namespace

ExampleDevice::ExampleDevice(Node& node, uint32_t serialNumber) noexcept
    : node_(node),
      serialNumber_(serialNumber),
      attached_(node.attachHook(kCommand, kCommand, *this) &&
                node.attachHook(kScratchPad, kScratchPad, *this) &&
                node.attachHook(kOperatingMode, kOperatingMode, *this) && node.addListener(*this)) {
}

void ExampleDevice::onResetApplication() noexcept {
  epoch_ = node_.now();
  scratchPadLength_ = 0;
}

void ExampleDevice::onResetCommunication() noexcept {
  node_.dictionary().storeUnsigned(0x1018, 4, serialNumber_);
}

Microseconds ExampleDevice::process(Microseconds now) noexcept {
  const Microseconds elapsed = now > epoch_ ? now - epoch_ : 0U;
  node_.dictionary().storeUnsigned(kUptime, 0, elapsed / kSecond);
  return epoch_ + (elapsed / kSecond + 1U) * kSecond;
}

AbortCode ExampleDevice::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                               const uint8_t* data, size_t length) noexcept {
  if (ref.index() == kOperatingMode && node_.state() != NmtState::kPreOperational) {
    return AbortCode::kCannotStoreState;
  }
  const AbortCode checked = dictionary.check(ref, data, length);
  if (checked != AbortCode::kNone) {
    return checked;
  }
  if (ref.index() == kCommand) {
    if (data[0] == kSelfTest) {
      return AbortCode::kGeneral;
    }
    if (data[0] == kRestartUptime) {
      epoch_ = node_.now();
      dictionary.storeUnsigned(kUptime, 0, 0);
    }
  }
  return dictionary.write(ref, data, length);
}

AbortCode ExampleDevice::readStream(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                                    size_t offset, uint8_t* destination, size_t capacity,
                                    size_t* produced, size_t* totalSize) noexcept {
  if (ref.index() != kScratchPad) {
    return ObjectHook::readStream(dictionary, ref, offset, destination, capacity, produced,
                                  totalSize);
  }
  const size_t available = offset < scratchPadLength_ ? scratchPadLength_ - offset : 0U;
  *produced = capacity < available ? capacity : available;
  *totalSize = scratchPadLength_;
  if (*produced > 0U) {
    memcpy(destination, scratchPad_ + offset, *produced);
  }
  return AbortCode::kNone;
}

AbortCode ExampleDevice::writeStream(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                                     size_t offset, const uint8_t* source, size_t length, bool last,
                                     size_t indicatedSize) noexcept {
  if (ref.index() != kScratchPad) {
    return ObjectHook::writeStream(dictionary, ref, offset, source, length, last, indicatedSize);
  }
  if (indicatedSize != kSizeNotIndicated && indicatedSize > kScratchPadCapacity) {
    return AbortCode::kLengthTooHigh;
  }
  if (offset > kScratchPadCapacity || length > kScratchPadCapacity - offset) {
    return AbortCode::kLengthTooHigh;
  }
  if (offset == 0U) {
    scratchPadLength_ = 0;  // the old content is overwritten from here on
    receiving_ = true;
  }
  if (length > 0U) {
    memcpy(scratchPad_ + offset, source, length);
  }
  if (last) {
    scratchPadLength_ = offset + length;
    receiving_ = false;
  }
  return AbortCode::kNone;
}

void ExampleDevice::abortWriteStream(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                                     AbortCode reason) noexcept {
  if (ref.index() != kScratchPad) {
    ObjectHook::abortWriteStream(dictionary, ref, reason);
    return;
  }
  if (receiving_) {
    scratchPadLength_ = 0;  // partly overwritten: nothing valid is left
    receiving_ = false;
  }
}

}  // namespace costa::example
