#include "costa/safety_service.hpp"

#include "costa/node_events.hpp"

namespace costa {

bool SafetyService::gfcValid() const noexcept {
  return dictionary_.readUnsigned(kGfcIndex, 0, 0) == 1U;
}

void SafetyService::addRoutes(FrameRouter& router) const noexcept {
  if (gfcValid()) {
    (void)router.add(kGfcCanId, Route::kGfc);
  }
}

bool SafetyService::onGfc(const CanFrame& frame) noexcept {
  if (frame.rtr || frame.dlc != 0U) {
    return false;
  }
  listeners_.notify([](NodeEvents& listener) { listener.onGlobalFailSafe(); });
  return true;
}

bool SafetyService::sendGfc(bool allowed) noexcept {
  if (!allowed || !gfcValid()) {
    return false;
  }
  CanFrame frame;
  frame.id = kGfcCanId;
  frame.dlc = 0;
  tx_.send(frame);
  return true;
}

AbortCode SafetyService::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                               const uint8_t* data, size_t length) noexcept {
  if (ref.index() == kGfcIndex && length == 1U && data[0] > 1U) {
    return AbortCode::kInvalidValue;
  }
  const AbortCode written = dictionary.write(ref, data, length);
  if (written == AbortCode::kNone && ref.index() == kGfcIndex) {
    routes_.invalidate();
  }
  return written;
}

}  // namespace costa
