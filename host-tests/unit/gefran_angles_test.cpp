// The two angles of a GRA on the wire: each from its own hall chip (manual line 450, errata
// E24), each with its own direction 0x2102 (E27) and resolution 0x2100 (E26), seen in the TPDO
// bytes and in 0x2000 read by SDO.
#include <gtest/gtest.h>

#include "device_fixture.hpp"

namespace costa::test {
namespace {

class GraAngles : public DeviceTest {
 protected:
  GraAngles() : DeviceTest("gra", -1) {}  // the factory node-id 0x7F

  void SetUp() override {
    EXPECT_TRANSCRIPT(R"(
      tx 77F [1] 00
      tx 1FF [8] 00 00 00 00 FF FF FF 00   # operational by itself (E17)
    )");
  }
};

TEST_F(GraAngles, EachAngleComesFromItsOwnChip) {
  // Angle 1 CCW: 100 x 3600 / 16384 = 21.97 -> 21 (0x0015).
  // Angle 2 CW (factory, E27): (16384 - 9000) x 3600 / 16384 = 1622.46 -> 1622 (0x0656).
  EXPECT_TRANSCRIPT(R"(
    sim raw 100 9000
    wait 100
    tx 1FF [8] 00 15 06 56 FF FF FF 00
    rx 67F [8] 40 00 20 01 00 00 00 00     # 0x2000:01, raw reading of chip 1
    tx 5FF [8] 4B 00 20 01 64 00 00 00     # 100
    rx 67F [8] 40 00 20 02 00 00 00 00     # 0x2000:02, raw reading of chip 2
    tx 5FF [8] 4B 00 20 02 28 23 00 00     # 9000
  )");
  // The other way round: angle 1 = 9000 x 3600 / 16384 = 1977 (0x07B9),
  // angle 2 = 16284 x 3600 / 16384 = 3578 (0x0DFA).
  EXPECT_TRANSCRIPT(R"(
    sim raw 9000 100
    wait 100
    tx 1FF [8] 07 B9 0D FA FF FF FF 00
    rx 67F [8] 40 00 20 01 00 00 00 00
    tx 5FF [8] 4B 00 20 01 28 23 00 00
    rx 67F [8] 40 00 20 02 00 00 00 00
    tx 5FF [8] 4B 00 20 02 64 00 00 00
  )");
}

TEST_F(GraAngles, EachAngleHasItsOwnDirection) {
  // 0x2102: 0 = CCW (the raw reading), 1 = CW (16384 - raw). Raw 100 / 9000 as above:
  // angle 1 CCW 21 (0x0015) or CW 3578 (0x0DFA); angle 2 CCW 1977 (0x07B9) or CW 1622 (0x0656).
  EXPECT_TRANSCRIPT(R"(
    sim raw 100 9000
    wait 100
    tx 1FF [8] 00 15 06 56 FF FF FF 00     # factory: angle 1 CCW, angle 2 CW
    rx 67F [8] 2F 02 21 01 01 00 00 00     # 0x2102:01 = 1: angle 1 CW
    tx 5FF [8] 60 02 21 01 00 00 00 00
    wait 100
    tx 1FF [8] 0D FA 06 56 FF FF FF 00     # angle 1 turned round, angle 2 unchanged
    rx 67F [8] 2F 02 21 02 00 00 00 00     # 0x2102:02 = 0: angle 2 CCW
    tx 5FF [8] 60 02 21 02 00 00 00 00
    wait 100
    tx 1FF [8] 0D FA 07 B9 FF FF FF 00     # angle 2 turned round, angle 1 unchanged
    rx 67F [8] 2F 02 21 01 00 00 00 00     # 0x2102:01 = 0: angle 1 CCW again
    tx 5FF [8] 60 02 21 01 00 00 00 00
    wait 100
    tx 1FF [8] 00 15 07 B9 FF FF FF 00
    rx 67F [8] 40 02 21 02 00 00 00 00
    tx 5FF [8] 4F 02 21 02 00 00 00 00
  )");
}

TEST_F(GraAngles, OneDegreeResolutionOnTheWire) {
  // Both chips at 270 deg (raw 12288). Angle 1 at 1 deg: 270 (0x010E); angle 2 (CW) at 0.01 deg:
  // 90.00 (9000, 0x2328), then at 1 deg: 90 (0x005A).
  EXPECT_TRANSCRIPT(R"(
    sim angle 270
    wait 100
    tx 1FF [8] 0A 8C 03 84 FF FF FF 00     # 270.0 / 90.0 at the factory 0.1 deg
    rx 67F [8] 2B 00 21 01 E8 03 00 00     # 0x2100:01 = 1000: 1 deg
    tx 5FF [8] 60 00 21 01 00 00 00 00
    rx 67F [8] 2B 00 21 02 16 00 00 00     # 0x2100:02 = 22: 0.01 deg
    tx 5FF [8] 60 00 21 02 00 00 00 00
    wait 100
    tx 1FF [8] 01 0E 23 28 FF FF FF 00
    rx 67F [8] 2B 00 21 02 E8 03 00 00     # 0x2100:02 = 1000
    tx 5FF [8] 60 00 21 02 00 00 00 00
    wait 100
    tx 1FF [8] 01 0E 00 5A FF FF FF 00
  )");
}

}  // namespace
}  // namespace costa::test
