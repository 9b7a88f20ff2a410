// Node::writeEntry: a device's own write of an entry, through the entry's hook (a service's too)
// as an SDO download would go, without access rights. On the example device.
#include "example_fixture.hpp"

namespace costa::test {
namespace {

class WriteEntry : public ExampleNodeTest {
 protected:
  AbortCode write(uint16_t index, uint8_t subIndex, uint32_t number, size_t length) {
    uint8_t data[4] = {};
    storeU32(data, number);
    AbortCode result = AbortCode::kGeneral;
    withNode([&](Node& node) { result = node.writeEntry(index, subIndex, data, length); });
    return result;
  }
};

TEST_F(WriteEntry, HeartbeatTimeRestartsTheProducer) {
  EXPECT_EQ(write(0x1017, 0, 100, 2), AbortCode::kNone);
  EXPECT_TRANSCRIPT(R"(
    wait 99
    silence
    wait 1
    tx 701 [1] 7F
    wait 100
    tx 701 [1] 7F
  )");
  EXPECT_EQ(write(0x1017, 0, 0, 2), AbortCode::kNone);
  EXPECT_TRANSCRIPT(R"(
    wait 1000
    silence
  )");
}

TEST_F(WriteEntry, TpdoEventTimerTakesEffect) {
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 01
    wait 1000
    silence
  )");
  EXPECT_EQ(write(0x1800, 5, 100, 2), AbortCode::kNone);
  EXPECT_TRANSCRIPT(R"(
    wait 99
    silence
    wait 1
    tx 181 [6] 01 00 00 00 D7 00         # uptime 1 s, temperature 215
    wait 100
    tx 181 [6] 01 00 00 00 D7 00
  )");
}

TEST_F(WriteEntry, WritesReadOnlyRamEntriesButNotConstants) {
  EXPECT_EQ(write(0x2011, 0, 300, 2), AbortCode::kNone);  // ro: no access rights asked
  EXPECT_EQ(value(0x2011, 0), 300U);
  EXPECT_EQ(write(0x1000, 0, 1, 4), AbortCode::kWriteOfReadOnly);  // const: in ROM
}

TEST_F(WriteEntry, RefusesAsAnSdoDownloadWould) {
  EXPECT_EQ(write(0x2099, 0, 1, 1), AbortCode::kNoObject);
  EXPECT_EQ(write(0x2004, 9, 1, 1), AbortCode::kNoSubIndex);
  EXPECT_EQ(write(0x2000, 0, 5, 4), AbortCode::kValueTooLow);  // limits 10..100000
  EXPECT_EQ(write(0x2000, 0, 500, 2), AbortCode::kLengthTooLow);
  EXPECT_EQ(value(0x2000, 0), 1000U);
  EXPECT_TRANSCRIPT("silence");  // no frame for a local write
}

}  // namespace
}  // namespace costa::test
