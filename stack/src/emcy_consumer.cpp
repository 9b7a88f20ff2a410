#include "costa/emcy_consumer.hpp"

#include "costa/cob_ids.hpp"
#include "costa/node_events.hpp"
#include "costa/od/little_endian.hpp"

namespace costa {
namespace {

constexpr uint32_t kNotValid = 0x80000000U;
constexpr uint32_t kExtended = 0x20000000U;
constexpr uint32_t kReserved = 0x1FFFF800U;
constexpr uint8_t kLength = 8;

}  // namespace

void EmcyConsumer::addRoutes(const od::ObjectDictionary& dictionary, FrameRouter& router) noexcept {
  // Without the object the count is 0: no route.
  const auto count = static_cast<uint8_t>(dictionary.readUnsigned32(kIndex, 0, 0));
  for (uint8_t sub = 1; sub != 0U && sub <= count; ++sub) {
    const auto value = dictionary.readUnsigned32(kIndex, sub, kNotValid);
    if ((value & (kNotValid | kExtended | kReserved)) == 0U) {
      (void)router.add(static_cast<uint16_t>(value & 0x7FFU), Route::kEmcy, sub);
    }
  }
}

bool EmcyConsumer::onFrame(const CanFrame& frame, uint8_t entry) noexcept {
  if (frame.rtr || frame.dlc != kLength) {
    ++framesIgnored_;
    return false;
  }
  EmcyMessage emcy;
  emcy.canId = static_cast<uint16_t>(frame.id);
  const uint32_t offset = frame.id - cob::kEmcyBase;  // 1..127: the pre-defined 0x80 + node-id
  emcy.producer = offset >= 1U && offset <= 127U ? static_cast<uint8_t>(offset) : 0U;
  emcy.entry = entry;
  emcy.errorCode = loadU16(frame.data);
  emcy.errorRegister = frame.data[2];
  for (size_t i = 0; i < sizeof(emcy.manufacturer); ++i) {
    emcy.manufacturer[i] = frame.data[3U + i];
  }
  listeners_.notify([&emcy](NodeEvents& listener) { listener.onEmcyReceived(emcy); });
  return true;
}

AbortCode EmcyConsumer::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                              const uint8_t* data, size_t length) noexcept {
  if (ref.subIndex() != 0U && length == 4U) {
    // A valid entry uses its CAN-ID; nothing keeps it from changing (no `kept` rule).
    const uint32_t value = loadU32(data);
    if (!cob::acceptableCobId(value, (value & kNotValid) == 0U, false, 0)) {
      return AbortCode::kInvalidValue;
    }
  }
  const AbortCode written = dictionary.write(ref, data, length);
  if (written == AbortCode::kNone) {
    routes_.invalidate();
  }
  return written;
}

}  // namespace costa
