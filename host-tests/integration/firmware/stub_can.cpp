#include "stub_can.hpp"

namespace sensor {

bool StubCan::tryTransmit(const costa::CanFrame& frame) noexcept {
  if (controller_.bitRate == 0U || controller_.txFull != 0U) {
    return false;
  }
  controller_.tx = frame;
  controller_.txFull = 1U;
  return true;
}

bool StubCan::setBitRate(uint32_t bitsPerSecond) noexcept {
  if (bitsPerSecond < 10000U || bitsPerSecond > 1000000U) {
    return false;
  }
  controller_.bitRate = bitsPerSecond;
  return true;
}

bool StubCan::receive(costa::CanFrame* frame) noexcept {
  if (controller_.rxFull == 0U) {
    return false;
  }
  *frame = controller_.rx;
  controller_.rxFull = 0U;
  return true;
}

bool StubCan::setFilters(const costa::CanIdFilter* filters, size_t count) noexcept {
  if (count > StubController::kFilters) {
    controller_.filterCount = StubController::kAcceptAll;
    return false;
  }
  controller_.filterCount = 0;  // none while they change
  for (size_t i = 0; i < count; ++i) {
    controller_.filterId[i] = filters[i].id;
    controller_.filterMask[i] = filters[i].mask;
  }
  controller_.filterCount = static_cast<uint32_t>(count);
  return true;
}

}  // namespace sensor
