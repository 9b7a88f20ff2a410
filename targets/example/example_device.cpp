#include "example_device.hpp"

#include "costa/od/bytes.hpp"

namespace costa::example {
namespace {
constexpr Microseconds kSecond = 1000000;
constexpr uint8_t kRestartUptime = 1;
constexpr uint8_t kSelfTest = 3;
}  // namespace

// The scratch pad is left uninitialised on purpose: only its first scratchPadLength_ bytes count.
// cppcheck-suppress uninitMemberVar ; the scratch pad's unused bytes mean nothing
// NOLINTNEXTLINE(cppcoreguidelines-pro-type-member-init)
ExampleDevice::ExampleDevice(Node& node, uint32_t serialNumber) noexcept
    : node_(node),
      clock_(node),
      serialNumber_(serialNumber),
      attached_(node.attachHook(kCommand, kCommand, *this) &&
                node.attachHook(kScratchPad, kScratchPad, *this) &&
                node.attachHook(kOperatingMode, kOperatingMode, *this) &&
                node.attachHook(ExampleClock::kIndex, ExampleClock::kIndex, clock_) &&
                node.addListener(*this)) {}

void ExampleDevice::onResetApplication() noexcept {
  restartUptime();
  scratchPadLength_ = 0;
}

void ExampleDevice::onResetCommunication() noexcept {
  node_.dictionary().storeUnsigned(0x1018, 4, serialNumber_);
}

void ExampleDevice::onEmcyReceived(const EmcyMessage& emcy) noexcept {
  od::ObjectDictionary& dictionary = node_.dictionary();
  dictionary.storeUnsigned(kLastEmergency, 1, emcy.producer);
  dictionary.storeUnsigned(kLastEmergency, 2, emcy.errorCode);
  dictionary.storeUnsigned(kLastEmergency, 3, emcy.errorRegister);
  dictionary.storeUnsigned(kLastEmergency, 4, dictionary.readUnsigned(kLastEmergency, 4, 0) + 1U);
}

void ExampleDevice::restartUptime() noexcept {
  secondStart_ = node_.now();
  uptime_ = 0;
}

Microseconds ExampleDevice::process(Microseconds now) noexcept {
  // Whole seconds counted one by one: the uptime goes on past the wrap of the 32-bit clock.
  while (now - secondStart_ >= kSecond) {
    secondStart_ += kSecond;
    ++uptime_;
  }
  node_.dictionary().storeUnsigned(kUptime, 0, uptime_);
  return at(secondStart_, kSecond);
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
      restartUptime();
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
    copyBytes(destination, scratchPad_ + offset, *produced);
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
    copyBytes(scratchPad_ + offset, source, length);
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
