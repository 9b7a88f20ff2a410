// The M-series joint's dictionary (targets/mseries/mseries.eds) on the wire: every object of the
// manual's lists (lines 325-388, 535-669) and the additions (A1-A3) read back with the size its
// address gives (line 322, D1-D22), with the defaults decided (A4); what is fixed or read-only
// refuses writes; ranges and the hook's refusals answer their abort codes.
#include <string>
#include <vector>

#include "mseries_fixture.hpp"

namespace costa::test {
namespace {

using JointDictionary = JointTest;

struct Upload {
  const char* request;   ///< index and sub-index bytes: "17 10 00"
  const char* response;  ///< the whole response after the command byte's own checks
};

std::string uploads(const std::vector<Upload>& table) {
  std::string text;
  for (const Upload& u : table) {
    text += std::string("rx 601 [8] 40 ") + u.request + " 00 00 00 00\n";
    text += std::string("tx 581 [8] ") + u.response + "\n";
  }
  return text;
}

TEST_F(JointDictionary, CommunicationObjects) {
  EXPECT_TRANSCRIPT(uploads({
      {"00 10 00", "43 00 10 00 92 01 02 00"},  // 0x00020192: CiA 402 servo drive (line 328)
      {"01 10 00", "4F 01 10 00 00 00 00 00"},  // A1
      {"05 10 00", "43 05 10 00 80 00 00 00"},  // 0x80 (D2)
      {"16 10 00", "4F 16 10 00 01 00 00 00"},
      {"16 10 01", "43 16 10 01 D0 07 7F 00"},  // 0x007F07D0 (line 764)
      {"17 10 00", "4B 17 10 00 E8 03 00 00"},  // 1000 ms (line 750)
      {"18 10 00", "4F 18 10 00 04 00 00 00"},  // UNSIGNED8 (D1)
      {"18 10 01", "43 18 10 01 31 03 00 00"},  // 0x331
      {"18 10 02", "43 18 10 02 01 00 00 00"},
      {"18 10 03", "43 18 10 03 00 01 00 00"},  // 0x100
      {"18 10 04", "43 18 10 04 01 00 00 00"},
  }));
}

TEST_F(JointDictionary, FixedPdos) {
  EXPECT_TRANSCRIPT(uploads({
      {"00 14 00", "4F 00 14 00 03 00 00 00"},
      {"00 14 01", "43 00 14 01 01 02 00 00"},  // 0x201: the COB-ID itself (D8)
      {"00 14 02", "4F 00 14 02 FF 00 00 00"},
      {"00 14 03", "4B 00 14 03 01 00 00 00"},
      {"01 14 01", "43 01 14 01 01 03 00 00"},
      {"02 14 01", "43 02 14 01 01 04 00 00"},
      {"03 14 01", "43 03 14 01 01 05 00 00"},
      {"03 14 02", "4F 03 14 02 01 00 00 00"},  // RPDO4: at the SYNC
      {"00 16 00", "4F 00 16 00 03 00 00 00"},
      {"00 16 01", "43 00 16 01 10 00 40 60"},
      {"00 16 02", "43 00 16 02 08 00 60 60"},
      {"00 16 03", "43 00 16 03 20 00 7A 60"},
      {"01 16 00", "4F 01 16 00 02 00 00 00"},
      {"01 16 01", "43 01 16 01 20 00 7A 60"},
      {"01 16 02", "43 01 16 02 20 00 81 60"},
      {"02 16 03", "43 02 16 03 20 00 FF 60"},
      {"03 16 00", "4F 03 16 00 01 00 00 00"},
      {"03 16 01", "43 03 16 01 20 00 7A 60"},
      {"00 18 01", "43 00 18 01 81 01 00 40"},  // 0x181, no RTR (W9)
      {"00 18 02", "4F 00 18 02 FF 00 00 00"},
      {"00 18 03", "4B 00 18 03 03 00 00 00"},  // 0.3 ms (D7)
      {"01 18 01", "43 01 18 01 81 02 00 40"},
      {"02 18 01", "43 02 18 01 81 03 00 40"},
      {"03 18 01", "43 03 18 01 81 04 00 40"},
      {"00 1A 01", "43 00 1A 01 20 00 64 60"},
      {"00 1A 02", "43 00 1A 02 10 00 41 60"},
      {"02 1A 01", "43 02 1A 01 20 00 6C 60"},  // TPDO3: velocity (D6)
      {"03 1A 01", "43 03 1A 01 20 00 64 60"},
  }));
}

TEST_F(JointDictionary, VendorObjects) {
  EXPECT_TRANSCRIPT(uploads({
      {"00 26 00", "4B 00 26 00 00 00 00 00"},
      {"01 26 00", "4B 01 26 00 01 00 00 00"},
      {"04 26 00", "4B 04 26 00 00 00 00 00"},
      {"09 26 00", "4B 09 26 00 00 00 00 00"},
      {"0A 26 00", "4B 0A 26 00 00 80 00 00"},  // 32768 (line 257)
      {"0B 26 00", "4B 0B 26 00 00 20 00 00"},  // 8192 (line 159)
      {"0C 26 00", "43 0C 26 00 00 00 00 00"},
      {"0E 26 00", "4B 0E 26 00 00 00 00 00"},
      {"12 26 00", "4B 12 26 00 1E 00 00 00"},  // 30 degrees
      {"13 26 00", "4B 13 26 00 00 00 00 00"},
      {"14 26 00", "4B 14 26 00 00 00 00 00"},
      {"15 26 00", "4B 15 26 00 01 00 00 00"},
      {"18 26 00", "4B 18 26 00 2C 01 00 00"},  // 300
      {"19 26 00", "4B 19 26 00 00 00 00 00"},
      {"1C 26 00", "4B 1C 26 00 00 00 00 00"},
      {"1D 26 00", "4B 1D 26 00 88 13 00 00"},  // 5000 mA
  }));
}

TEST_F(JointDictionary, DriveObjects) {
  EXPECT_TRANSCRIPT(uploads({
      {"40 60 00", "4B 40 60 00 00 00 00 00"},
      {"41 60 00", "4B 41 60 00 04 04 00 00"},  // pulse control, at rest (B7)
      {"60 60 00", "4F 60 60 00 00 00 00 00"},
      {"61 60 00", "4F 61 60 00 00 00 00 00"},  // A2
      {"63 60 00", "43 63 60 00 00 00 00 00"},
      {"64 60 00", "43 64 60 00 00 00 00 00"},
      {"6C 60 00", "43 6C 60 00 00 00 00 00"},  // INTEGER32 (D5)
      {"78 60 00", "4B 78 60 00 64 00 00 00"},  // 100 / 2000 A at rest
      {"79 60 00", "4B 79 60 00 FC 2D 00 00"},  // 36 V x 327 (D13)
      {"7A 60 00", "43 7A 60 00 00 00 00 00"},
      {"81 60 00", "43 81 60 00 E8 03 00 00"},  // 1000 r/min (A4)
      {"83 60 00", "43 83 60 00 20 4E 00 00"},  // 20000 (r/min)/s (A4)
      {"98 60 00", "4F 98 60 00 11 00 00 00"},  // 17 (A4)
      {"F9 60 01", "4B F9 60 01 E8 03 00 00"},
      {"F9 60 02", "4B F9 60 02 64 00 00 00"},
      {"FB 60 01", "4B FB 60 01 E8 03 00 00"},
      {"FB 60 02", "4B FB 60 02 47 01 00 00"},  // 327 (D16)
      {"FD 60 00", "4B FD 60 00 00 00 00 00"},  // 16-bit (D13)
      {"FF 60 00", "43 FF 60 00 00 00 00 00"},
      {"02 65 00", "43 02 65 00 65 00 00 00"},  // modes 1, 3, 6, 7 (A3)
  }));
}

TEST_F(JointDictionary, ObjectsTheJointDoesNotHave) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 10 10 01 00 00 00 00   # no store command: 0x2614 saves (B13)
    tx 581 [8] 80 10 10 01 00 00 02 06
    rx 601 [8] 40 14 10 00 00 00 00 00   # no EMCY (W10)
    tx 581 [8] 80 14 10 00 00 00 02 06
    rx 601 [8] 40 29 10 00 00 00 00 00   # no error behaviour
    tx 581 [8] 80 29 10 00 00 00 02 06
    rx 601 [8] 40 0C 10 00 00 00 00 00   # no node guarding (W9)
    tx 581 [8] 80 0C 10 00 00 00 02 06
    rx 601 [8] 40 C1 60 00 00 00 00 00   # interpolation from 0x607A, not 0x60C1 (B8)
    tx 581 [8] 80 C1 60 00 00 00 02 06
  )");
}

TEST_F(JointDictionary, PdoParametersCannotBeChanged) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 00 14 01 81 02 00 80   # RPDO1 COB-ID
    tx 581 [8] 80 00 14 01 02 00 01 06
    rx 601 [8] 2F 03 14 02 FF 00 00 00   # RPDO4 type
    tx 581 [8] 80 03 14 02 02 00 01 06
    rx 601 [8] 2F 00 16 00 00 00 00 00   # RPDO1 mapping count
    tx 581 [8] 80 00 16 00 02 00 01 06
    rx 601 [8] 2B 00 18 03 01 00 00 00   # TPDO1 inhibit
    tx 581 [8] 80 00 18 03 02 00 01 06
    rx 601 [8] 23 02 1A 01 20 00 64 60   # TPDO3 mapping
    tx 581 [8] 80 02 1A 01 02 00 01 06
  )");
}

TEST_F(JointDictionary, ReadOnlyObjects) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 41 60 00 37 00 00 00
    tx 581 [8] 80 41 60 00 02 00 01 06
    rx 601 [8] 2F 61 60 00 01 00 00 00
    tx 581 [8] 80 61 60 00 02 00 01 06
    rx 601 [8] 23 64 60 00 01 00 00 00
    tx 581 [8] 80 64 60 00 02 00 01 06
    rx 601 [8] 23 6C 60 00 01 00 00 00   # ro, not the listed "Read&write" (D5)
    tx 581 [8] 80 6C 60 00 02 00 01 06
    rx 601 [8] 23 05 10 00 81 00 00 00   # read only as listed (D2)
    tx 581 [8] 80 05 10 00 02 00 01 06
    rx 601 [8] 23 00 10 00 00 00 00 00
    tx 581 [8] 80 00 10 00 02 00 01 06
  )");
}

TEST_F(JointDictionary, RangesAndRefusals) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 15 26 00 00 00 00 00   # node-id 0 (D11)
    tx 581 [8] 80 15 26 00 32 00 09 06
    rx 601 [8] 2B 15 26 00 80 00 00 00   # node-id 128 (D11)
    tx 581 [8] 80 15 26 00 31 00 09 06
    rx 601 [8] 2B 14 26 00 02 00 00 00   # 2 is read, not written (D10)
    tx 581 [8] 80 14 26 00 30 00 09 06
    rx 601 [8] 2B 14 26 00 03 00 00 00
    tx 581 [8] 80 14 26 00 31 00 09 06
    rx 601 [8] 2F 98 60 00 14 00 00 00   # homing method 20: no figure (D9)
    tx 581 [8] 80 98 60 00 30 00 09 06
    rx 601 [8] 2F 98 60 00 16 00 00 00   # 22
    tx 581 [8] 80 98 60 00 31 00 09 06
    rx 601 [8] 2F 98 60 00 10 00 00 00   # 16
    tx 581 [8] 80 98 60 00 32 00 09 06
    rx 601 [8] 2B 0E 26 00 12 00 00 00   # the alarm code takes only 0 (D18)
    tx 581 [8] 80 0E 26 00 30 00 09 06
    rx 601 [8] 2F 60 60 00 02 00 00 00   # mode 2: not in 0x6502
    tx 581 [8] 80 60 60 00 30 00 09 06
    rx 601 [8] 23 FF 60 00 B9 0B 00 00   # 3001 r/min
    tx 581 [8] 80 FF 60 00 31 00 09 06
    rx 601 [8] 23 FF 60 00 47 F4 FF FF   # -3001 r/min
    tx 581 [8] 80 FF 60 00 32 00 09 06
    rx 601 [8] 23 81 60 00 B9 0B 00 00   # 3001 r/min
    tx 581 [8] 80 81 60 00 31 00 09 06
    rx 601 [8] 2B 0B 26 00 00 00 00 00   # denominator 0
    tx 581 [8] 80 0B 26 00 32 00 09 06
    rx 601 [8] 2B 19 26 00 01 80 00 00   # 32769 (D12)
    tx 581 [8] 80 19 26 00 31 00 09 06
    rx 601 [8] 2B FB 60 02 55 0F 00 00   # 3925: above 12.0 V/KRPM (D16)
    tx 581 [8] 80 FB 60 02 31 00 09 06
    rx 601 [8] 23 40 60 00 0F 00 00 00   # a control word of 4 bytes
    tx 581 [8] 80 40 60 00 12 00 07 06
  )");
}

TEST_F(JointDictionary, ParametersAcceptTheirRange) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 98 60 00 15 00 00 00   # 21
    tx 581 [8] 60 98 60 00 00 00 00 00
    rx 601 [8] 2B 19 26 00 00 80 00 00   # 32768
    tx 581 [8] 60 19 26 00 00 00 00 00
    rx 601 [8] 23 FF 60 00 48 F4 FF FF   # -3000
    tx 581 [8] 60 FF 60 00 00 00 00 00
    rx 601 [8] 2B 15 26 00 7F 00 00 00   # 127
    tx 581 [8] 60 15 26 00 00 00 00 00
  )");
}

TEST_F(JointDictionary, EveryHookAndListenerFoundRoom) {
  EXPECT_TRUE(joint().attached());
}

}  // namespace
}  // namespace costa::test
