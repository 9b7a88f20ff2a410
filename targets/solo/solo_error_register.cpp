#include "solo_error_register.hpp"

namespace costa::solo {
namespace {

struct BitReport {
  uint16_t code;
  uint8_t registerBit;
};

constexpr BitReport kReports[7] = {
    {0x2310, kErrorCurrent},      {0x3210, kErrorVoltage},      {0x4210, kErrorTemperature},
    {0xFF03, kErrorManufacturer}, {0xFF04, kErrorManufacturer}, {0x8130, kErrorCommunication},
    {0xFF06, kErrorManufacturer},
};

}  // namespace

void SoloErrorRegister::assign(uint32_t bits) noexcept {
  value_ = bits;
  for (uint8_t bit = 0; bit < 7U; ++bit) {
    const uint32_t mask = 1U << bit;
    if ((bits & mask) != 0U && (reported_ & mask) == 0U) {
      node_.raiseError(kReports[bit].code, kReports[bit].registerBit, nullptr, bit);
    } else if ((bits & mask) == 0U && (reported_ & mask) != 0U) {
      node_.clearError(kReports[bit].code, bit);
    }
  }
  reported_ = bits & 0x7FU;
}

}  // namespace costa::solo
