// Device profile switches that change wire behaviour (each one also used by a device target).
#include "example_fixture.hpp"

namespace costa::test {
namespace {

class ProfileVariant : public ExampleNodeTest {
 protected:
  static NodeSettings settings() {
    NodeSettings settings;
    settings.profile.sdo.expeditedUpload = ExpeditedUploadFormat::kFourBytesSizeNotIndicated;
    settings.profile.sdo.distinguishHighAndLowValues = false;
    settings.profile.emcy.errorResetFrame = false;
    settings.profile.errorControl.emcyForErrors = false;
    return settings;
  }
  ProfileVariant() : ExampleNodeTest(settings()) {}
};

TEST_F(ProfileVariant, ExpeditedUploadsUse42WithFourBytes) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 10 20 00 00 00 00 00   # UNSIGNED8
    tx 581 [8] 42 10 20 00 00 00 00 00
    rx 601 [8] 40 11 20 00 00 00 00 00   # INTEGER16 215
    tx 581 [8] 42 11 20 00 D7 00 00 00
    rx 601 [8] 40 09 10 00 00 00 00 00   # 3-byte string
    tx 581 [8] 42 09 10 00 31 2E 30 00
    rx 601 [8] 40 08 10 00 00 00 00 00   # longer values are still segmented
    tx 581 [8] 41 08 10 00 0D 00 00 00
  )");
}

TEST_F(ProfileVariant, OutOfRangeWritesAbortWith06090030) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 00 20 00 A1 86 01 00   # too high
    tx 581 [8] 80 00 20 00 30 00 09 06
    rx 601 [8] 23 00 20 00 09 00 00 00   # too low
    tx 581 [8] 80 00 20 00 30 00 09 06
  )");
}

TEST_F(ProfileVariant, NoErrorResetEmcy) {
  withNode([](Node& node) { node.raiseError(0x5000, 0); });
  EXPECT_TRANSCRIPT("tx 081 [8] 00 50 01 00 00 00 00 00");
  withNode([](Node& node) { node.clearError(0x5000); });
  EXPECT_TRANSCRIPT("silence");
  EXPECT_EQ(value(0x1001, 0), 0U);
}

class LifeGuardEvents : public NodeEvents {
 public:
  void onLifeGuardingExpired() noexcept override { ++expired; }
  int expired = 0;
};

TEST_F(ProfileVariant, ErrorControlEventsWithoutEmcy) {
  LifeGuardEvents events;
  ASSERT_TRUE(bus_.node().addListener(events));
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 0C 10 00 0A 00 00 00
    tx 581 [8] 60 0C 10 00 00 00 00 00
    rx 601 [8] 2F 0D 10 00 01 00 00 00
    tx 581 [8] 60 0D 10 00 00 00 00 00
    rx 701 [0] RTR
    tx 701 [1] 7F
    wait 10
    silence
  )");
  EXPECT_EQ(events.expired, 1);
}

}  // namespace
}  // namespace costa::test
