#include "example_clock.hpp"

namespace costa::example {
namespace {
constexpr uint8_t kMilliseconds = 1;
constexpr uint8_t kDays = 2;
constexpr uint8_t kProducerPeriod = 3;
}  // namespace

AbortCode ExampleClock::prepareRead(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                                    const ReadRequest& request) noexcept {
  (void)request;
  TimeOfDay time;
  if (ref.subIndex() != kProducerPeriod && node_.timeOfDay(&time)) {
    dictionary.storeUnsigned(kIndex, kMilliseconds, time.milliseconds);
    dictionary.storeUnsigned(kIndex, kDays, time.days);
  }
  return AbortCode::kNone;
}

AbortCode ExampleClock::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                              const uint8_t* data, size_t length) noexcept {
  const AbortCode written = dictionary.write(ref, data, length);  // type, size and limits
  if (written != AbortCode::kNone) {
    return written;
  }
  const auto value = static_cast<uint32_t>(dictionary.readUnsigned(ref));
  if (ref.subIndex() == kProducerPeriod) {
    node_.setTimeProducerPeriod(millisecondsToMicroseconds(value));
    return AbortCode::kNone;
  }
  TimeOfDay time;
  if (!node_.timeOfDay(&time)) {
    time = TimeOfDay{};
  }
  if (ref.subIndex() == kMilliseconds) {
    time.milliseconds = value;
  } else {
    time.days = static_cast<uint16_t>(value);
  }
  return node_.setTimeOfDay(time) ? AbortCode::kNone : AbortCode::kInvalidValue;
}

}  // namespace costa::example
