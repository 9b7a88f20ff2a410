// BxCanPort::setFilters(): the node's acceptance filters in CAN1's filter banks (RM0090,
// "Identifier filtering": 16-bit scale, mask mode).
#include "costa/port/stm32/bxcan_port.hpp"

namespace costa::port::stm32 {
namespace {

constexpr uint32_t kBanks = 28;
/// A 16-bit filter half: STID[10:0] in bits 15:5, RTR bit 4, IDE bit 3, EXID[17:15] bits 2:0.
constexpr uint32_t kStidShift16 = 5;
constexpr uint32_t kIde16 = 1U << 3;

/// Identifier in the low half, mask in the high half: the standard identifier's bits of the
/// filter's mask must agree, IDE must be 0 (standard), RTR and EXID do not matter.
constexpr uint32_t halfBank(const CanIdFilter& filter) noexcept {
  const uint32_t id = (static_cast<uint32_t>(filter.id) & 0x7FFU) << kStidShift16;
  const uint32_t mask = ((static_cast<uint32_t>(filter.mask) & 0x7FFU) << kStidShift16) | kIde16;
  return (mask << 16U) | id;
}

}  // namespace

uint32_t BxCanPort::ownBanks() const noexcept {
  const uint32_t banks = (registers_.fmr & bxcan::fmr::kCan2sbMask) >> bxcan::fmr::kCan2sbShift;
  return (1U << (banks < kBanks ? banks : kBanks)) - 1U;  // at most 28 banks: bits 0..27
}

bool BxCanPort::setFilters(const CanIdFilter* filters, size_t count) noexcept {
  using namespace bxcan;
  const uint32_t own = ownBanks();
  size_t banks = 0;
  for (uint32_t bits = own; bits != 0U; bits >>= 1U) {
    ++banks;
  }
  if (count > 2U * banks) {
    acceptAllFrames();
    return false;
  }
  registers_.fmr = registers_.fmr | fmr::kFinit;
  registers_.fa1r = registers_.fa1r & ~own;    // a bank is changed while inactive
  registers_.fm1r = registers_.fm1r & ~own;    // mask mode
  registers_.fs1r = registers_.fs1r & ~own;    // two 16-bit filters
  registers_.ffa1r = registers_.ffa1r & ~own;  // into FIFO 0
  uint32_t active = 0;
  for (size_t bank = 0; 2U * bank < count; ++bank) {
    const CanIdFilter& first = filters[2U * bank];
    const CanIdFilter& second = 2U * bank + 1U < count ? filters[2U * bank + 1U] : first;
    registers_.filter[bank].fr1 = halfBank(first);
    registers_.filter[bank].fr2 = halfBank(second);
    active |= 1U << bank;
  }
  registers_.fa1r = registers_.fa1r | active;
  registers_.fmr = registers_.fmr & ~fmr::kFinit;
  return true;
}

void BxCanPort::acceptAllFrames() noexcept {
  using namespace bxcan;
  registers_.fmr = registers_.fmr | fmr::kFinit;
  registers_.fa1r = registers_.fa1r & ~ownBanks();
  registers_.fmr = registers_.fmr & ~fmr::kFinit;
  acceptEverythingIntoFifo0();
}

}  // namespace costa::port::stm32
