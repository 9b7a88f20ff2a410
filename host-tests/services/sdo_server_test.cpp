// SdoServer alone: expedited and segmented transfers, every abort, the timeout, hooks, the profile.
#include "costa/sdo_server.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "costa/hook_registry.hpp"
#include "costa/object_access.hpp"
#include "costa/service_objects.hpp"
#include "service_fixture.hpp"

namespace costa::test {
namespace {

/// A hook that records its calls and refuses what it is told to.
class RefusingHook final : public ObjectHook {
 public:
  AbortCode prepareRead(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                        const ReadRequest& request) noexcept override {
    (void)dictionary;
    (void)ref;
    ++reads;
    lastRequest = request;
    return readVerdict;
  }
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override {
    ++writes;
    return writeVerdict != AbortCode::kNone ? writeVerdict : dictionary.write(ref, data, length);
  }

  AbortCode readVerdict = AbortCode::kNone;
  AbortCode writeVerdict = AbortCode::kNone;
  int reads = 0;
  int writes = 0;
  ReadRequest lastRequest;
};

class SdoServerTest : public ServiceTest {
 protected:
  static constexpr Microseconds kTimeout = 500000;

  SdoServerTest()
      : hooks_(bindings_, 2),
        services_(ServiceObjects::Hooks{}),
        access_(dictionary_, hooks_, services_),
        sdo_(access_, tx_, profile_, clock_, buffer_, sizeof(buffer_), kTimeout) {
    sdo_.setNodeId(kNodeId);
  }

  /// A request from the client on 0x605; the server must take it.
  void request(std::initializer_list<uint8_t> bytes, Microseconds now = kStart) {
    EXPECT_TRUE(sdo_.onRequest(frame8(0x605, bytes), now));
    EXPECT_TRUE(sdo_.valid());
  }
  static CanFrame response(std::initializer_list<uint8_t> bytes) { return frame8(0x585, bytes); }
  static CanFrame abortOf(uint16_t index, uint8_t subIndex, AbortCode code) {
    const auto value = static_cast<uint32_t>(code);
    return response({0x80, static_cast<uint8_t>(index), static_cast<uint8_t>(index >> 8U), subIndex,
                     static_cast<uint8_t>(value), static_cast<uint8_t>(value >> 8U),
                     static_cast<uint8_t>(value >> 16U), static_cast<uint8_t>(value >> 24U)});
  }
  std::string label() const { return od_.values.x2003_device_label; }

  HookBinding bindings_[2];
  HookRegistry hooks_;
  ServiceObjects services_;
  ObjectAccess access_;
  SdoProfile profile_;
  uint8_t buffer_[32] = {};
  SdoServer sdo_;
};

TEST_F(SdoServerTest, ExpeditedUploadIndicatesTheSizeOfTheValue) {
  request({0x40, 0x00, 0x20, 0x01});
  request({0x40, 0x01, 0x20, 0x01});
  request({0x40, 0x01, 0x20, 0x02});
  request({0x40, 0x18, 0x10, 0x01});  // a constant, in ROM
  EXPECT_EQ(sent(), frames({response({0x4F, 0x00, 0x20, 0x01, 0x00}),
                            response({0x4B, 0x01, 0x20, 0x01, 0x34, 0x12}),
                            response({0x43, 0x01, 0x20, 0x02, 0xEF, 0xCD, 0xAB, 0x89}),
                            response({0x43, 0x18, 0x10, 0x01, 0x78, 0x56, 0x34, 0x12})}));
  EXPECT_FALSE(sdo_.busy());
}

TEST_F(SdoServerTest, ExpeditedDownloadWritesTheValueAndEchoesTheMultiplexer) {
  request({0x2F, 0x00, 0x20, 0x01, 0x07});
  request({0x2B, 0x00, 0x20, 0x02, 0x34, 0x12});
  request({0x22, 0x01, 0x20, 0x01, 0x78, 0x56, 0xFF, 0xFF});  // size not indicated: the entry's
  EXPECT_EQ(sent(), frames({response({0x60, 0x00, 0x20, 0x01}), response({0x60, 0x00, 0x20, 0x02}),
                            response({0x60, 0x01, 0x20, 0x01})}));
  EXPECT_EQ(value(0x2000, 1), 0x07U);
  EXPECT_EQ(value(0x2000, 2), 0x1234U);
  EXPECT_EQ(value(0x2001, 1), 0x5678U);
}

// Size not indicated (0x22) to an OCTET_STRING of 2 bytes: its own size, as for a number.
TEST_F(SdoServerTest, AnExpeditedDownloadWithoutSizeFillsAShortOctetString) {
  request({0x22, 0x09, 0x20, 0x00, 0xAB, 0xCD, 0xEE, 0xFF});
  EXPECT_EQ(sent(), frames({response({0x60, 0x09, 0x20, 0x00})}));
  uint8_t key[2] = {};
  EXPECT_EQ(dictionary_.read(dictionary_.find(0x2009, 0), 0, key, sizeof(key)), 2U);
  EXPECT_EQ(key[0], 0xABU);
  EXPECT_EQ(key[1], 0xCDU);
}

TEST_F(SdoServerTest, AccessesToMissingOrForbiddenEntriesAbortNamingTheEntry) {
  request({0x40, 0x00, 0x30, 0x00});                 // no object
  request({0x40, 0x00, 0x20, 0x09});                 // no sub-index
  request({0x40, 0x04, 0x20, 0x00});                 // write-only
  request({0x23, 0x05, 0x20, 0x00, 0x01, 0, 0, 0});  // read-only
  request({0x2F, 0x00, 0x10, 0x00, 0x01});           // constant
  EXPECT_EQ(sent(), frames({abortOf(0x3000, 0x00, AbortCode::kNoObject),
                            abortOf(0x2000, 0x09, AbortCode::kNoSubIndex),
                            abortOf(0x2004, 0x00, AbortCode::kReadOfWriteOnly),
                            abortOf(0x2005, 0x00, AbortCode::kWriteOfReadOnly),
                            abortOf(0x1000, 0x00, AbortCode::kWriteOfReadOnly)}));
  EXPECT_EQ(value(0x2005, 0), 0x01020304U);
}

TEST_F(SdoServerTest, ValuesOutsideTheLimitsOrOfTheWrongLengthAreRefused) {
  request({0x2F, 0x02, 0x20, 0x00, 21});
  request({0x2F, 0x02, 0x20, 0x00, 9});
  request({0x2B, 0x02, 0x20, 0x00, 15, 0});  // two bytes for an UNSIGNED8
  request({0x2F, 0x00, 0x20, 0x02, 0x01});   // one byte for an UNSIGNED16
  EXPECT_EQ(sent(), frames({abortOf(0x2002, 0x00, AbortCode::kValueTooHigh),
                            abortOf(0x2002, 0x00, AbortCode::kValueTooLow),
                            abortOf(0x2002, 0x00, AbortCode::kLengthTooHigh),
                            abortOf(0x2000, 0x02, AbortCode::kLengthTooLow)}));
  EXPECT_EQ(value(0x2002, 0), 15U);
  request({0x2F, 0x02, 0x20, 0x00, 20});  // the limit itself is allowed
  EXPECT_EQ(sent(), frames({response({0x60, 0x02, 0x20, 0x00})}));
}

TEST_F(SdoServerTest, SegmentedUploadAlternatesTheToggleAndMarksTheLastSegment) {
  request({0x40, 0x03, 0x20, 0x00});
  EXPECT_TRUE(sdo_.busy());
  request({0x60});
  request({0x70});
  EXPECT_EQ(sent(), frames({response({0x41, 0x03, 0x20, 0x00, 14, 0, 0, 0}),
                            response({0x00, 'C', 'o', 's', 't', 'a', ' ', 's'}),
                            response({0x11, 'e', 'r', 'v', 'i', 'c', 'e', 's'})}));
  EXPECT_FALSE(sdo_.busy());
  EXPECT_EQ(sdo_.nextDeadline(), kNever);
}

TEST_F(SdoServerTest, AnUploadSendsTheValueAsItWasAtTheInitiate) {
  request({0x40, 0x03, 0x20, 0x00});
  request({0x60});
  std::strcpy(od_.values.x2003_device_label, "Changed midway");  // the application writes
  request({0x70});
  EXPECT_EQ(sent(), frames({response({0x41, 0x03, 0x20, 0x00, 14, 0, 0, 0}),
                            response({0x00, 'C', 'o', 's', 't', 'a', ' ', 's'}),
                            response({0x11, 'e', 'r', 'v', 'i', 'c', 'e', 's'})}));
}

TEST_F(SdoServerTest, ASnapshotThatFillsTheBufferIsUploadedTheSame) {
  // 20 bytes hold the label (capacity 20) but not the 7 zeros that follow a snapshot when the
  // buffer has room (26 bytes and more here): the last segment is then copied by its length.
  const std::string text = "Costa services, too";  // 19 bytes: the last segment has 5
  std::strcpy(od_.values.x2003_device_label, text.c_str());
  for (const size_t size : {size_t{20}, size_t{26}, size_t{32}}) {
    std::memset(buffer_, 0xEE, sizeof(buffer_));  // what no segment may carry
    SdoServer server(access_, tx_, profile_, clock_, buffer_, size, kTimeout);
    server.setNodeId(kNodeId);
    EXPECT_TRUE(server.onRequest(frame8(0x605, {0x40, 0x03, 0x20, 0x00}), kStart));
    for (const uint8_t segment : {uint8_t{0x60}, uint8_t{0x70}, uint8_t{0x60}}) {
      EXPECT_TRUE(server.onRequest(frame8(0x605, {segment}), kStart)) << size;
    }
    EXPECT_EQ(sent(), frames({response({0x41, 0x03, 0x20, 0x00, 19, 0, 0, 0}),
                              response({0x00, 'C', 'o', 's', 't', 'a', ' ', 's'}),
                              response({0x10, 'e', 'r', 'v', 'i', 'c', 'e', 's'}),
                              response({0x05, ',', ' ', 't', 'o', 'o', 0, 0})}))
        << size;
    EXPECT_FALSE(server.busy());
  }
}

TEST_F(SdoServerTest, AWrongToggleBitAbortsTheTransfer) {
  request({0x40, 0x03, 0x20, 0x00});
  request({0x70});
  EXPECT_EQ(sent(), frames({response({0x41, 0x03, 0x20, 0x00, 14, 0, 0, 0}),
                            abortOf(0x2003, 0x00, AbortCode::kToggleBit)}));
  EXPECT_FALSE(sdo_.busy());
}

TEST_F(SdoServerTest, ASegmentedDownloadIsWrittenOnlyWhenComplete) {
  request({0x21, 0x03, 0x20, 0x00, 10, 0, 0, 0});
  request({0x00, 'H', 'e', 'l', 'l', 'o', ' ', 'w'});
  EXPECT_EQ(label(), "Costa services");
  request({0x19, 'o', 'r', 'l'});  // toggle 1, 4 bytes unused, last
  EXPECT_EQ(sent(),
            frames({response({0x60, 0x03, 0x20, 0x00}), response({0x20}), response({0x30})}));
  EXPECT_EQ(label(), "Hello worl");
  EXPECT_FALSE(sdo_.busy());
}

TEST_F(SdoServerTest, ADownloadLongerThanItsIndicatedSizeAbortsAndKeepsTheOldValue) {
  request({0x21, 0x03, 0x20, 0x00, 5, 0, 0, 0});
  request({0x00, 'H', 'e', 'l', 'l', 'o', ' ', 'w'});
  EXPECT_EQ(sent(), frames({response({0x60, 0x03, 0x20, 0x00}),
                            abortOf(0x2003, 0x00, AbortCode::kLengthMismatch)}));
  EXPECT_EQ(label(), "Costa services");
}

TEST_F(SdoServerTest, ASilentClientTimesOutAfterTheTimeout) {
  request({0x40, 0x03, 0x20, 0x00});
  EXPECT_EQ(clock_.next, after(kTimeout));  // the node hears of the deadline
  request({0x60}, after(100000));           // each request restarts the wait
  EXPECT_EQ(sdo_.nextDeadline(), after(100000 + kTimeout));
  sdo_.process(after(100000 + kTimeout - 1U));
  EXPECT_TRUE(sdo_.busy());
  sdo_.process(after(100000 + kTimeout));
  EXPECT_FALSE(sdo_.busy());
  const std::vector<std::string> all = sent();
  ASSERT_EQ(all.size(), 3U);
  EXPECT_EQ(all[2], describe(abortOf(0x2003, 0x00, AbortCode::kTimeout)));
  EXPECT_TRUE(sdo_.valid());
}

TEST_F(SdoServerTest, FramesOtherThanEightDataBytesAreIgnored) {
  CanFrame shortRequest = frame(0x605, {0x40, 0x00, 0x20, 0x01});
  EXPECT_FALSE(sdo_.onRequest(shortRequest, kStart));
  CanFrame remoteRequest = frame8(0x605, {0x40, 0x00, 0x20, 0x01});
  remoteRequest.rtr = true;
  EXPECT_FALSE(sdo_.onRequest(remoteRequest, kStart));
  EXPECT_TRUE(sent().empty());
}

TEST_F(SdoServerTest, UnknownCommandsAndSegmentsWithoutATransferAbort) {
  request({0xE0, 0x00, 0x20, 0x01});
  request({0x60, 0x00, 0x20, 0x01});
  EXPECT_EQ(sent(), frames({abortOf(0x2000, 0x01, AbortCode::kCommandSpecifier),
                            abortOf(0x0000, 0x00, AbortCode::kCommandSpecifier)}));
}

TEST_F(SdoServerTest, AClientAbortEndsTheTransferWithoutAnAnswer) {
  request({0x21, 0x03, 0x20, 0x00, 10, 0, 0, 0});
  request({0x00, 'H', 'e', 'l', 'l', 'o', ' ', 'w'});
  request({0x80, 0x03, 0x20, 0x00, 0x00, 0x00, 0x00, 0x08});
  EXPECT_FALSE(sdo_.busy());
  EXPECT_EQ(sent().size(), 2U);
  EXPECT_EQ(label(), "Costa services");
}

TEST_F(SdoServerTest, ResetDropsTheTransferSilently) {
  request({0x40, 0x03, 0x20, 0x00});
  sdo_.reset();
  EXPECT_FALSE(sdo_.busy());
  EXPECT_EQ(sdo_.nextDeadline(), kNever);
  request({0x60});
  EXPECT_EQ(sent(), frames({response({0x41, 0x03, 0x20, 0x00, 14, 0, 0, 0}),
                            abortOf(0x0000, 0x00, AbortCode::kCommandSpecifier)}));
}

TEST_F(SdoServerTest, AnApplicationHookDecidesReadsAndWritesOfItsEntries) {
  RefusingHook hook;
  ASSERT_TRUE(hooks_.attach(0x2000, 0x2001, hook));
  hook.readVerdict = AbortCode::kNoData;
  hook.writeVerdict = AbortCode::kHardwareError;
  request({0x40, 0x00, 0x20, 0x01, 0xAA, 0xBB, 0xCC, 0xDD});
  request({0x2F, 0x00, 0x20, 0x01, 0x07});
  request({0x40, 0x02, 0x20, 0x00});  // not behind the hook
  EXPECT_EQ(sent(), frames({abortOf(0x2000, 0x01, AbortCode::kNoData),
                            abortOf(0x2000, 0x01, AbortCode::kHardwareError),
                            response({0x4F, 0x02, 0x20, 0x00, 15})}));
  EXPECT_EQ(hook.reads, 1);
  EXPECT_EQ(hook.writes, 1);
  EXPECT_EQ(hook.lastRequest.requestData[0], 0xAAU);  // the request's bytes 4..7 reach it
  EXPECT_EQ(hook.lastRequest.requestData[3], 0xDDU);
  EXPECT_EQ(value(0x2000, 1), 0U);
}

TEST_F(SdoServerTest, ADomainWithoutAHookCannotBeStored) {
  request({0x21, 0x06, 0x20, 0x00, 4, 0, 0, 0});
  request({0x23, 0x06, 0x20, 0x00, 1, 2, 3, 4});
  EXPECT_EQ(sent(), frames({abortOf(0x2006, 0x00, AbortCode::kCannotStore),
                            abortOf(0x2006, 0x00, AbortCode::kCannotStore)}));
  EXPECT_FALSE(sdo_.busy());
}

TEST_F(SdoServerTest, AValueLargerThanTheBufferNeedsAStreamingHook) {
  uint8_t small[8] = {};
  SdoServer server(access_, tx_, profile_, clock_, small, sizeof(small), kTimeout);
  server.setNodeId(kNodeId);
  EXPECT_TRUE(server.onRequest(frame8(0x605, {0x21, 0x03, 0x20, 0x00, 10, 0, 0, 0}), kStart));
  EXPECT_EQ(sent(), frames({abortOf(0x2003, 0x00, AbortCode::kOutOfMemory)}));
  EXPECT_FALSE(server.busy());
}

TEST_F(SdoServerTest, TheProfileChoosesTheExpeditedFormatAndTheOutOfRangeCode) {
  SdoProfile profile;
  profile.expeditedUpload = ExpeditedUploadFormat::kFourBytesSizeNotIndicated;
  profile.distinguishHighAndLowValues = false;
  SdoServer server(access_, tx_, profile, clock_, buffer_, sizeof(buffer_), kTimeout);
  server.setNodeId(kNodeId);
  EXPECT_TRUE(server.onRequest(frame8(0x605, {0x40, 0x01, 0x20, 0x01}), kStart));
  EXPECT_TRUE(server.onRequest(frame8(0x605, {0x2F, 0x02, 0x20, 0x00, 21}), kStart));
  EXPECT_TRUE(server.onRequest(frame8(0x605, {0x2F, 0x02, 0x20, 0x00, 9}), kStart));
  EXPECT_EQ(sent(), frames({response({0x42, 0x01, 0x20, 0x01, 0x34, 0x12, 0x00, 0x00}),
                            abortOf(0x2002, 0x00, AbortCode::kInvalidValue),
                            abortOf(0x2002, 0x00, AbortCode::kInvalidValue)}));
}

}  // namespace
}  // namespace costa::test
