#include "example_device.hpp"

namespace costa::example {
namespace {
constexpr Microseconds kSecond = 1000000;
constexpr uint8_t kRestartUptime = 1;
constexpr uint8_t kSelfTest = 3;
}  // namespace

ExampleDevice::ExampleDevice(Node& node, uint32_t serialNumber) noexcept
    : node_(node), serialNumber_(serialNumber) {
  node.attachHook(kCommand, kCommand, *this);
  node.attachHook(kOperatingMode, kOperatingMode, *this);
  node.setEvents(this);
}

void ExampleDevice::onResetApplication() noexcept {
  epoch_ = node_.now();
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
  const AbortCode checked = dictionary.check(*ref.entry, data, length);
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
  return dictionary.write(*ref.entry, data, length);
}

}  // namespace costa::example
