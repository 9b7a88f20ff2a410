// Writes to PDO communication and mapping parameters: CiA 301's rules and abort codes, and the
// dynamic mapping procedure.
#include "example_fixture.hpp"

namespace costa::test {
namespace {

using PdoConfig = ExampleNodeTest;

TEST_F(PdoConfig, CobIdRules_06090030) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 00 18 01 82 01 00 00   # another CAN-ID while valid
    tx 581 [8] 80 00 18 01 30 00 09 06
    rx 601 [8] 23 00 18 01 81 01 00 20   # bit 29: 29-bit CAN-ID
    tx 581 [8] 80 00 18 01 30 00 09 06
    rx 601 [8] 23 00 18 01 81 09 00 00   # bits 28..11 in an 11-bit COB-ID
    tx 581 [8] 80 00 18 01 30 00 09 06
    rx 601 [8] 23 00 18 01 81 01 00 80   # invalidate
    tx 581 [8] 60 00 18 01 00 00 00 00
    rx 601 [8] 23 00 18 01 01 07 00 00   # restricted CAN-ID 0x701 (NMT error control)
    tx 581 [8] 80 00 18 01 30 00 09 06
    rx 601 [8] 23 00 18 01 81 05 00 00   # restricted 0x581 (SDO)
    tx 581 [8] 80 00 18 01 30 00 09 06
    rx 601 [8] 23 00 18 01 01 07 00 80   # a restricted id is fine while invalid
    tx 581 [8] 60 00 18 01 00 00 00 00
    rx 601 [8] 23 00 18 01 90 01 00 00   # new CAN-ID 0x190, valid
    tx 581 [8] 60 00 18 01 00 00 00 00
    rx 000 [2] 01 01
    rx 190 [0] RTR
    tx 190 [6] 00 00 00 00 D7 00
  )");
}

TEST_F(PdoConfig, RpdoCobIdWith29BitFrameIsRefused_06090030) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 00 14 01 01 02 00 20   # bit 29 on the valid RPDO's own CAN-ID
    tx 581 [8] 80 00 14 01 30 00 09 06
    rx 601 [8] 23 00 14 01 01 02 00 A0   # bit 29 while invalid: still no 29-bit CAN-ID
    tx 581 [8] 80 00 14 01 30 00 09 06
    rx 601 [8] 40 00 14 01 00 00 00 00   # unchanged
    tx 581 [8] 43 00 14 01 01 02 00 00
    rx 000 [2] 01 01
    rx 201 [5] 2A 00 00 00 00            # the RPDO still receives on 0x201 (11-bit)
  )");
  EXPECT_EQ(value(0x2000, 0), 42U);
}

TEST_F(PdoConfig, TransmissionTypeRules_06090030) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 00 18 02 F1 00 00 00   # 241..251 reserved for TPDOs
    tx 581 [8] 80 00 18 02 30 00 09 06
    rx 601 [8] 2F 00 18 02 FB 00 00 00
    tx 581 [8] 80 00 18 02 30 00 09 06
    rx 601 [8] 2F 00 18 02 FC 00 00 00   # 252 is fine for a TPDO
    tx 581 [8] 60 00 18 02 00 00 00 00
    rx 601 [8] 2F 00 14 02 FC 00 00 00   # 241..253 reserved for RPDOs
    tx 581 [8] 80 00 14 02 30 00 09 06
    rx 601 [8] 2F 00 14 02 F0 00 00 00
    tx 581 [8] 60 00 14 02 00 00 00 00
  )");
}

TEST_F(PdoConfig, MappingChangesOnlyWhileInvalidAndDisabled_08000022) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 00 1A 00 00 00 00 00   # TPDO1 is valid
    tx 581 [8] 80 00 1A 00 22 00 00 08
    rx 601 [8] 23 00 1A 01 20 00 00 20
    tx 581 [8] 80 00 1A 01 22 00 00 08
    rx 601 [8] 23 02 1A 01 20 00 00 20   # TPDO3 invalid, but its mapping is enabled
    tx 581 [8] 80 02 1A 01 22 00 00 08
  )");
}

TEST_F(PdoConfig, MappingEntryChecks) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 02 1A 00 00 00 00 00   # TPDO3 mapping disabled
    tx 581 [8] 60 02 1A 00 00 00 00 00
    rx 601 [8] 23 02 1A 01 08 00 10 20   # 0x2010 is not mappable
    tx 581 [8] 80 02 1A 01 41 00 04 06
    rx 601 [8] 23 02 1A 01 20 00 02 20   # 0x2002 write-only: not in a TPDO
    tx 581 [8] 80 02 1A 01 41 00 04 06
    rx 601 [8] 23 02 1A 01 08 00 05 00   # dummy entries only in RPDOs
    tx 581 [8] 80 02 1A 01 41 00 04 06
    rx 601 [8] 23 02 1A 01 20 00 00 30   # no object 0x3000
    tx 581 [8] 80 02 1A 01 00 00 02 06
    rx 601 [8] 23 02 1A 01 20 09 04 20   # no sub-index 9
    tx 581 [8] 80 02 1A 01 11 00 09 06
    rx 601 [8] 23 02 1A 01 10 00 00 20   # 16 bits of a 32-bit object
    tx 581 [8] 80 02 1A 01 43 00 04 06
    rx 601 [8] 23 02 16 01 20 00 01 20   # 0x2001 read-only: not in an RPDO
    tx 581 [8] 80 02 16 01 41 00 04 06
  )");
}

// A COB-ID, mapping count or mapping entry written with the wrong length gets the dictionary's
// length abort, not the abort of a PDO rule its bytes would break as a value of that length,
// and changes nothing. (The transmission type is checked by its value first, so that a master
// that writes it as a wider type hears what is wrong with the value; 1 breaks no rule.)
TEST_F(PdoConfig, AParameterOfTheWrongLengthIsRefusedByItsLength) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 00 14 01 01 02 00 A0   # RPDO1 COB-ID (UNSIGNED32) in 2 bytes (as 4: 29-bit)
    tx 581 [8] 80 00 14 01 13 00 07 06
    rx 601 [8] 2B 00 18 02 01 00 00 00   # TPDO1 type (UNSIGNED8) in 2 bytes
    tx 581 [8] 80 00 18 02 12 00 07 06
    rx 601 [8] 23 02 1A 00 09 00 00 00   # TPDO3 mapping count (UNSIGNED8) in 4 bytes (9)
    tx 581 [8] 80 02 1A 00 12 00 07 06
    rx 601 [8] 40 02 1A 00 00 00 00 00   # still one entry
    tx 581 [8] 4F 02 1A 00 01 00 00 00
    rx 601 [8] 2F 02 1A 00 00 00 00 00   # TPDO3 mapping disabled
    tx 581 [8] 60 02 1A 00 00 00 00 00
    rx 601 [8] 2B 02 1A 01 00 30 00 00   # a mapping entry (UNSIGNED32) in 2 bytes
    tx 581 [8] 80 02 1A 01 13 00 07 06
    rx 601 [8] 40 00 14 01 00 00 00 00
    tx 581 [8] 43 00 14 01 01 02 00 00
    rx 601 [8] 40 00 18 02 00 00 00 00
    tx 581 [8] 4F 00 18 02 FF 00 00 00
    rx 601 [8] 40 02 1A 01 00 00 00 00
    tx 581 [8] 43 02 1A 01 20 00 00 20
  )");
}

TEST_F(PdoConfig, EnablingAMappingChecksItsLength_06040042) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 02 1A 00 00 00 00 00
    tx 581 [8] 60 02 1A 00 00 00 00 00
    rx 601 [8] 23 02 1A 01 40 05 04 20   # 64 bits
    tx 581 [8] 60 02 1A 01 00 00 00 00
    rx 601 [8] 23 02 1A 02 20 00 00 20   # + 32 bits
    tx 581 [8] 60 02 1A 02 00 00 00 00
    rx 601 [8] 2F 02 1A 00 02 00 00 00
    tx 581 [8] 80 02 1A 00 42 00 04 06
    rx 601 [8] 2F 02 1A 00 09 00 00 00   # more entries than a PDO holds
    tx 581 [8] 80 02 1A 00 42 00 04 06
    rx 601 [8] 2F 02 1A 00 03 00 00 00   # entry 3 is empty
    tx 581 [8] 80 02 1A 00 43 00 04 06
    rx 601 [8] 2F 02 1A 00 01 00 00 00   # the 64 bits alone are fine
    tx 581 [8] 60 02 1A 00 00 00 00 00
  )");
}

TEST_F(PdoConfig, TheCiaProcedureRemapsAPdo) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 00 18 01 81 01 00 80   # 1. invalidate TPDO1
    tx 581 [8] 60 00 18 01 00 00 00 00
    rx 601 [8] 2F 00 1A 00 00 00 00 00   # 2. disable the mapping
    tx 581 [8] 60 00 1A 00 00 00 00 00
    rx 601 [8] 23 00 1A 01 10 00 11 20   # 3. entries: temperature, setpoint, offset
    tx 581 [8] 60 00 1A 01 00 00 00 00
    rx 601 [8] 23 00 1A 02 20 00 00 20
    tx 581 [8] 60 00 1A 02 00 00 00 00
    rx 601 [8] 23 00 1A 03 08 02 04 20
    tx 581 [8] 60 00 1A 03 00 00 00 00
    rx 601 [8] 2F 00 1A 00 03 00 00 00   # 4. enable three entries
    tx 581 [8] 60 00 1A 00 00 00 00 00
    rx 601 [8] 23 00 18 01 81 01 00 00   # 5. validate
    tx 581 [8] 60 00 18 01 00 00 00 00
    rx 000 [2] 01 01
    rx 181 [0] RTR
    tx 181 [7] D7 00 E8 03 00 00 FB
  )");
}

TEST_F(PdoConfig, ResetCommunicationRestoresTheDefaultMapping) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 00 18 01 81 01 00 80
    tx 581 [8] 60 00 18 01 00 00 00 00
    rx 601 [8] 2F 00 1A 00 00 00 00 00
    tx 581 [8] 60 00 1A 00 00 00 00 00
    rx 000 [2] 82 01
    tx 701 [1] 00
    rx 000 [2] 01 01
    rx 181 [0] RTR
    tx 181 [6] 00 00 00 00 D7 00
  )");
}

}  // namespace
}  // namespace costa::test
