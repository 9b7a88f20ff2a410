// The SOLO data formats against every worked example of the SOLO manual
// (shared/manuals/solo-motor-controller-canopen.txt). Where the manual prints a wrong figure the
// test asserts the correct one and says what was printed; docs/errata-solo.md has the details.
#include <gtest/gtest.h>

#include <cstdio>
#include <limits>
#include <string>

#include "sfxt.hpp"

namespace costa::solo {
namespace {

// A data field from the bytes of a frame, in the order they are printed (LSB first).
uint32_t fromFrame(uint8_t b0, uint8_t b1, uint8_t b2, uint8_t b3) {
  const uint8_t bytes[4] = {b0, b1, b2, b3};
  return loadData(bytes);
}

// The four frame bytes of a raw Sfxt value, as text "b0 b1 b2 b3".
std::string frameBytes(int32_t raw) {
  uint8_t bytes[4] = {};
  storeData(int32ToData(raw), bytes);
  char text[12] = {};
  std::snprintf(text, sizeof(text), "%02X %02X %02X %02X", unsigned{bytes[0]}, unsigned{bytes[1]},
                unsigned{bytes[2]}, unsigned{bytes[3]});
  return text;
}

TEST(SoloLittleEndian, DataFieldTravelsLeastSignificantByteFirst) {
  // Lines 316-320: 0x87963510 is sent as 0x10 0x35 0x96 0x87.
  uint8_t bytes[4] = {};
  storeData(0x87963510U, bytes);
  EXPECT_EQ(bytes[0], 0x10U);
  EXPECT_EQ(bytes[1], 0x35U);
  EXPECT_EQ(bytes[2], 0x96U);
  EXPECT_EQ(bytes[3], 0x87U);
  EXPECT_EQ(loadData(bytes), 0x87963510U);
}

TEST(SfxtToDouble, PositiveExample) {
  // Lines 1663-1670: 0x00030000 = 196608, / 131072 = 1.5.
  EXPECT_EQ(sfxtToDouble(dataToInt32(0x00030000U)), 1.5);
}

TEST(SfxtToDouble, NegativeExample) {
  // Lines 1672-1680 print (0xFFFFFFFF - 0xFFFFCDD2) + 1 = 0x0003322E = 209454, so -1.598.
  // The difference is 0x0000322E = 12846: 0xFFFFCDD2 is -12846 / 2^17 = -0.0980072...
  EXPECT_EQ(dataToInt32(0xFFFFCDD2U), -12846);
  EXPECT_EQ(sfxtToDouble(dataToInt32(0xFFFFCDD2U)), -0.0980072021484375);
  // -1.598 (-209454) is the data field 0xFFFCCDD2, one digit more than printed.
  EXPECT_EQ(int32ToData(-209454), 0xFFFCCDD2U);
  EXPECT_EQ(sfxtToDouble(dataToInt32(0xFFFCCDD2U)), -1.5980072021484375);
}

TEST(SfxtToDouble, SignIsBit31NotTheManualsThreshold) {
  // Lines 1652 and 1657 call everything above 0x7FFE0000 negative. 0x7FFE0001..0x7FFFFFFF are
  // positive: their procedure would turn 0x7FFF0000 into -16384.5.
  EXPECT_EQ(sfxtToDouble(dataToInt32(0x7FFE0000U)), 16383.0);
  EXPECT_EQ(sfxtToDouble(dataToInt32(0x7FFF0000U)), 16383.5);
  EXPECT_EQ(sfxtToDouble(dataToInt32(0x7FFFFFFFU)), 16383.99999237060546875);
  EXPECT_EQ(sfxtToDouble(dataToInt32(0x80000000U)), -16384.0);
  EXPECT_EQ(sfxtToDouble(dataToInt32(0xFFFFFFFFU)), -0.00000762939453125);
}

TEST(SfxtFromDouble, PositiveExample) {
  // Lines 1703-1711: 4.2 * 2^17 = 550502.4 -> 550502, printed "0x0086666" (seven digits):
  // the data field is 0x00086666.
  EXPECT_EQ(sfxtFromDouble(4.2), 550502);
  EXPECT_EQ(int32ToData(sfxtFromDouble(4.2)), 0x00086666U);
  EXPECT_EQ(frameBytes(sfxtFromDouble(4.2)), "66 66 08 00");
}

TEST(SfxtFromDouble, NegativeExample) {
  // Lines 1713-1722: -14.36 * 2^17 = -1882193.92. The manual truncates to -1882193 (step 2,
  // "round down") and then subtracts from 0xFFFFFFFF without the +1 of the two's complement
  // (step 4), printing 0xFFE347AE. That data field is -1882194, which is also the nearest step,
  // so the printed result is right for Costa's rounding but does not follow from step 2:
  // -1882193 is 0xFFE347AF.
  EXPECT_EQ(sfxtFromDouble(-14.36), -1882194);
  EXPECT_EQ(int32ToData(sfxtFromDouble(-14.36)), 0xFFE347AEU);
  EXPECT_EQ(int32ToData(-1882193), 0xFFE347AFU);
  EXPECT_EQ(frameBytes(sfxtFromDouble(-14.36)), "AE 47 E3 FF");
}

TEST(SfxtFromDouble, ExactNegativeValuesKeepTheirValue) {
  // The manual's negative procedure (lines 1696-1701) lacks the +1: for -1.5 it gives
  // 0xFFFFFFFF - 0x00030000 = 0xFFFCFFFF, which its own decoding reads as -1.50000763.
  EXPECT_EQ(int32ToData(sfxtFromDouble(-1.5)), 0xFFFD0000U);
  EXPECT_EQ(sfxtToDouble(sfxtFromDouble(-1.5)), -1.5);
}

TEST(SfxtFromDouble, SpeedControllerGainsOfTheSpeedExamples) {
  // Lines 1839 and 1889: "Kp Gain to 0.01" with data 33 33 00 00. 0x3333 = 13107 is 0.1
  // (0.0999985); 0.01 is 1310.72 steps, nearest 1311 = 1F 05 00 00.
  EXPECT_EQ(frameBytes(sfxtFromDouble(0.01)), "1F 05 00 00");
  EXPECT_EQ(sfxtToDouble(dataToInt32(fromFrame(0x33, 0x33, 0x00, 0x00))), 0.0999984741210937500);
  EXPECT_EQ(frameBytes(sfxtFromDouble(0.1)), "33 33 00 00");
  // Lines 1841, 1867, 1891: "Ki Gain to 0.0008" with data 68 00 00 00 = 104, the manual's
  // truncation of 104.8576; the nearest step is 105 = 69 00 00 00.
  EXPECT_EQ(frameBytes(sfxtFromDouble(0.0008)), "69 00 00 00");
  EXPECT_EQ(sfxtToDouble(dataToInt32(fromFrame(0x68, 0x00, 0x00, 0x00))), 0.00079345703125);
  EXPECT_EQ(sfxtToDouble(sfxtFromDouble(0.0008)), 0.00080108642578125);
  // Line 1865: "Kp Gain to 0.5" with data 00 00 01 00 = 0x00010000 = 65536: correct.
  EXPECT_EQ(frameBytes(sfxtFromDouble(0.5)), "00 00 01 00");
  EXPECT_EQ(sfxtToDouble(dataToInt32(fromFrame(0x00, 0x00, 0x01, 0x00))), 0.5);
}

TEST(SfxtFromDouble, BoundsAndDefaultsOfTheObjectTables) {
  // The printed bounds and defaults of the object tables, as targets/solo/solo.eds holds them:
  // the nearest step of each printed figure (errata D19).
  EXPECT_EQ(sfxtFromDouble(0.0001), 13);           // 0x300D printed low bound (widened to 0: D9)
  EXPECT_EQ(sfxtFromDouble(0.0000001), 0);         // 0x300E low: below one step
  EXPECT_EQ(sfxtFromDouble(0.5), 65536);           // 0x300E high
  EXPECT_EQ(sfxtFromDouble(25.0), 3276800);        // 0x300D high
  EXPECT_EQ(sfxtFromDouble(32.0), 4194304);        // 0x3003 default and current limits
  EXPECT_EQ(sfxtFromDouble(100.0), 13107200);      // 0x3006 high
  EXPECT_EQ(sfxtFromDouble(300.0), 39321600);      // 0x300A/0x300B high
  EXPECT_EQ(sfxtFromDouble(16000.0), 2097152000);  // 0x3017.. high
  EXPECT_EQ(sfxtFromDouble(0.55), 72090);          // 0x3021/0x3022 high (72089.6)
  EXPECT_EQ(sfxtFromDouble(0.15), 19661);          // 0x3021 default (19660.8)
  EXPECT_EQ(sfxtFromDouble(0.25), 32768);          // 0x3022 default
  EXPECT_EQ(sfxtFromDouble(0.01), 1311);           // 0x3023 low (1310.72)
  EXPECT_EQ(sfxtFromDouble(1000.0), 131072000);    // 0x3023 high
  EXPECT_EQ(sfxtFromDouble(50.0), 6553600);        // 0x3023 default
  EXPECT_EQ(sfxtFromDouble(1.0), 131072);          // 0x3028/0x3029 high
  EXPECT_EQ(sfxtFromDouble(1600.0), 209715200);    // 0x302A/0x302B high
  EXPECT_EQ(sfxtFromDouble(-60.0), -7864320);      // 0x302D.. low
  EXPECT_EQ(sfxtFromDouble(-64.0), -8388608);      // 0x3034/0x3035 low
  EXPECT_EQ(sfxtFromDouble(-2.0), -262144);        // 0x3038 low
  EXPECT_EQ(sfxtFromDouble(-30.0), -3932160);      // 0x3039 low
  EXPECT_EQ(sfxtFromDouble(150.0), 19660800);      // 0x3039 high
  EXPECT_EQ(sfxtFromDouble(3.3), 432538);          // 0x3047 high (432537.6)
}

TEST(SfxtFromDouble, RoundsToNearestWithTiesAwayFromZero) {
  const double step = 1.0 / 131072.0;
  EXPECT_EQ(sfxtFromDouble(0.49 * step), 0);
  EXPECT_EQ(sfxtFromDouble(0.5 * step), 1);
  EXPECT_EQ(sfxtFromDouble(-0.5 * step), -1);
  EXPECT_EQ(sfxtFromDouble(-0.49 * step), 0);
  EXPECT_EQ(sfxtFromDouble(2.5 * step), 3);
  EXPECT_EQ(sfxtFromDouble(-2.5 * step), -3);
  EXPECT_EQ(sfxtFromDouble(-2.51 * step), -3);
  // Just below a tie: adding 0.5 and truncating would give 1 here.
  EXPECT_EQ(sfxtFromDouble(0.49999999999999994 * step), 0);
  EXPECT_EQ(sfxtFromDouble(0.0), 0);
  EXPECT_EQ(sfxtFromDouble(-0.0), 0);
}

TEST(SfxtFromDouble, SaturatesOutsideTheRange) {
  // Line 1626 gives the range as -16384.000 to 16384.000; +16384 itself is one step too far.
  const double step = 1.0 / 131072.0;
  EXPECT_EQ(sfxtFromDouble(16384.0), kSfxtRawMax);
  EXPECT_EQ(sfxtFromDouble(16384.0 - 0.5 * step), kSfxtRawMax);
  EXPECT_EQ(sfxtFromDouble(16384.0 - 0.51 * step), kSfxtRawMax);
  EXPECT_EQ(sfxtFromDouble(16384.0 - 1.51 * step), kSfxtRawMax - 1);
  EXPECT_EQ(sfxtFromDouble(-16384.0), kSfxtRawMin);
  EXPECT_EQ(sfxtFromDouble(-16384.0 - 0.49 * step), kSfxtRawMin);
  EXPECT_EQ(sfxtFromDouble(-16384.0 - 0.5 * step), kSfxtRawMin);
  EXPECT_EQ(sfxtFromDouble(-16384.0 + 0.51 * step), kSfxtRawMin + 1);
  EXPECT_EQ(sfxtFromDouble(1e300), kSfxtRawMax);
  EXPECT_EQ(sfxtFromDouble(-1e300), kSfxtRawMin);
  EXPECT_EQ(sfxtFromDouble(std::numeric_limits<double>::infinity()), kSfxtRawMax);
  EXPECT_EQ(sfxtFromDouble(-std::numeric_limits<double>::infinity()), kSfxtRawMin);
  EXPECT_EQ(sfxtFromDouble(std::numeric_limits<double>::quiet_NaN()), 0);
}

TEST(SfxtFromDouble, EveryRawValueSurvivesARoundTrip) {
  for (int64_t raw = INT32_MIN; raw <= INT32_MAX; raw += 65521) {
    const auto value = static_cast<int32_t>(raw);
    ASSERT_EQ(sfxtFromDouble(sfxtToDouble(value)), value);
  }
  for (const int32_t raw : {INT32_MIN, INT32_MIN + 1, -1, 0, 1, INT32_MAX - 1, INT32_MAX}) {
    EXPECT_EQ(sfxtFromDouble(sfxtToDouble(raw)), raw);
  }
}

TEST(Int32Data, HexToInt32Examples) {
  // Lines 1740-1744: 0x0003F393 = +258963.
  EXPECT_EQ(dataToInt32(0x0003F393U), 258963);
  // Lines 1746-1754 print the data as "0xFFCA8AD" (seven digits). As printed it is 0x0FFCA8AD,
  // a positive number; the worked result -218963 belongs to 0xFFFCA8AD.
  EXPECT_EQ(dataToInt32(0xFFFCA8ADU), -218963);
  EXPECT_EQ(dataToInt32(0x0FFCA8ADU), 268216493);
  EXPECT_EQ(dataToInt32(0x7FFFFFFFU), INT32_MAX);
  EXPECT_EQ(dataToInt32(0x80000000U), INT32_MIN);
  EXPECT_EQ(dataToInt32(0xFFFFFFFFU), -1);
}

TEST(Int32Data, Int32ToHexExamples) {
  // Lines 1774-1778: 1536 = 0x00000600.
  EXPECT_EQ(int32ToData(1536), 0x00000600U);
  // Lines 1780-1784: -56329 = 4294967295 - 56329 + 1 = 0xFFFF23F7.
  EXPECT_EQ(int32ToData(-56329), 0xFFFF23F7U);
  EXPECT_EQ(int32ToData(INT32_MIN), 0x80000000U);
  EXPECT_EQ(int32ToData(-1), 0xFFFFFFFFU);
}

TEST(Int32Data, PositionsInThePdoExamples) {
  // Lines 1918 and 1925: target position 0x001A1A00 travels as 00 1A 1A 00.
  EXPECT_EQ(dataToInt32(fromFrame(0x00, 0x1A, 0x1A, 0x00)), 0x001A1A00);
  EXPECT_EQ(dataToInt32(fromFrame(0x00, 0x1A, 0x1A, 0x00)), 1710592);
  // Lines 1961, 1963, 1982, 1987, 2003: position feedback in TPDO 0x280.
  EXPECT_EQ(dataToInt32(fromFrame(0x60, 0xD5, 0x71, 0xFE)), -26094240);
  EXPECT_EQ(dataToInt32(fromFrame(0xF1, 0xCA, 0x71, 0xFE)), -26096911);
}

TEST(Int32Data, UnsignedFieldsOfTheExamples) {
  // Line 1802: guard time 3000 ms = B8 0B 00 00; line 1818: 1000 ms = E8 03 00 00;
  // line 1899: 6000 RPM = 70 17 00 00; lines 1921 and 1956: COB-ID words of the PDO examples.
  EXPECT_EQ(fromFrame(0xB8, 0x0B, 0x00, 0x00), 3000U);
  EXPECT_EQ(fromFrame(0xE8, 0x03, 0x00, 0x00), 1000U);
  EXPECT_EQ(fromFrame(0x70, 0x17, 0x00, 0x00), 6000U);
  EXPECT_EQ(fromFrame(0x01, 0x02, 0x00, 0xC0), 0xC0000201U);
  EXPECT_EQ(fromFrame(0x80, 0x02, 0x00, 0xC0), 0xC0000280U);
}

}  // namespace
}  // namespace costa::solo
