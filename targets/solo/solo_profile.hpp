// The SOLO's wire behaviour as a Costa device profile, and its fixed PDO mappings
// (docs/errata-solo.md, section P).
#pragma once

#include "costa/node.hpp"

namespace costa::solo {

/// Each PDO carries one 32-bit object (manual lines 544-560).
inline constexpr StaticPdoMapping kPdoMappings[] = {
    {0x1414, 1, {0x301B0020}},  // RPDO1: position reference
    {0x1415, 1, {0x30050020}},  // RPDO2: speed reference
    {0x1416, 1, {0x30040020}},  // RPDO3: torque reference (Iq)
    {0x1417, 1, {0x301A0020}},  // RPDO4: direct current reference (Id)
    {0x1418, 1, {0x30160020}},  // RPDO5: control mode
    {0x1419, 1, {0x300C0020}},  // RPDO6: motor direction
    {0x1814, 1, {0x30370020}},  // TPDO1: position feedback
    {0x1815, 1, {0x30360020}},  // TPDO2: speed feedback
    {0x1816, 1, {0x30340020}},  // TPDO3: Iq feedback
    {0x1817, 1, {0x30350020}},  // TPDO4: Id feedback
    {0x1818, 1, {0x30200020}},  // TPDO5: device error register
    {0x1819, 1, {0x30390020}},  // TPDO6: board temperature
};

/// The SOLO profile: 0x42 upload responses (P1), PDO COB-ID bit 31 enables and bit 30 allows
/// RTR (P3), EMCY with the error register in the fourth byte and no error-reset frame (P4, S6),
/// TPDO type 0 at every SYNC and RTR for every type (P6), COB-ID ranges (P7), 0x06090030 for
/// every range violation (P8), node-guarding toggle starting at 1 (A12), life guarding reported
/// through the device error register 0x3020 (S5), the fixed PDO mappings above (P5).
constexpr DeviceProfile profile() noexcept {
  DeviceProfile p{};
  // The device needs the quirk profiles (solo_target.cpp); its header compiles in any tree.
#if COSTA_QUIRK_PROFILES
  p.sdo.expeditedUpload = ExpeditedUploadFormat::kFourBytesSizeNotIndicated;
  p.pdo.cobIdPolarity = PdoCobIdPolarity::kBit31EnablesBit30AllowsRtr;
  p.pdo.tpdoType0 = TpdoType0::kEverySync;
  p.pdo.tpdoRtrTypes = TpdoRtrTypes::kAllTypes;
  p.pdo.rpdoCanIds = CanIdRange{0x200, 0x27F};
  p.pdo.tpdoCanIds = CanIdRange{0x280, 0x2FF};
  p.emcy.layout = EmcyLayout::kErrorRegisterInFourthByte;
  p.errorControl.guardToggleStart = 1;
  p.sdo.distinguishHighAndLowValues = false;
  p.emcy.errorResetFrame = false;
  p.errorControl.emcyForErrors = false;
  p.pdo.staticMappings =
      StaticPdoMappings{kPdoMappings, sizeof(kPdoMappings) / sizeof(kPdoMappings[0])};
#endif
  return p;
}

}  // namespace costa::solo
