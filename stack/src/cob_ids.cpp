// The COB-ID write rules that SYNC, TIME, EMCY, the EMCY consumer and the PDOs share (CiA 301).
#include "costa/cob_ids.hpp"

namespace costa::cob {

bool acceptableCobId(uint32_t value, bool used, bool kept, uint32_t currentCanId) noexcept {
  constexpr uint32_t kExtendedOrReserved = 0x3FFFF800U;  // bit 29 and bits 11..28
  const uint32_t canId = value & 0x7FFU;
  return (value & kExtendedOrReserved) == 0U && !(used && isRestrictedCanId(canId)) &&
         !(kept && canId != currentCanId);
}

}  // namespace costa::cob
