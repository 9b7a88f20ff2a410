// EmcyProducer alone: EMCY frames, 0x1001, 0x1003, 0x1014, 0x1015, full tables and its profile.
#include "costa/emcy_producer.hpp"

#include <gtest/gtest.h>

#include "service_fixture.hpp"

namespace costa::test {
namespace {

class EmcyProducerTest : public ServiceTest {
 protected:
  static constexpr size_t kConditions = 2;
  static constexpr size_t kPending = 3;

  EmcyProducerTest()
      : emcy_(dictionary_, profile_, clock_, conditions_, kConditions, pending_, kPending) {
    emcy_.setNodeId(kNodeId);
  }

  void send(NmtState state = NmtState::kPreOperational) { emcy_.process(clock_.now, state, tx_); }

  EmcyProfile profile_;
  EmcyCondition conditions_[kConditions];
  PendingEmcy pending_[kPending];
  EmcyProducer emcy_;
};

const uint8_t kManufacturer[5] = {0xA1, 0xA2, 0xA3, 0xA4, 0xA5};

/// An EMCY frame of the CiA 301 layout: code, register, manufacturer-specific bytes.
CanFrame emcy(uint16_t code, uint8_t errorRegister, const uint8_t* manufacturer = nullptr,
              uint32_t id = 0x85) {
  CanFrame result = frame(id, {static_cast<uint8_t>(code), static_cast<uint8_t>(code >> 8U),
                               errorRegister, 0, 0, 0, 0, 0});
  for (size_t i = 0; manufacturer != nullptr && i < 5U; ++i) {
    result.data[3U + i] = manufacturer[i];
  }
  return result;
}

// CiA 301's error code classes and the error register bits they name; the other classes (generic,
// device hardware and software, modules, monitoring other than communication and protocol, as
// CiA 402's speed and position errors, external) name none but the generic bit, which every
// condition sets.
TEST(ErrorRegisterBitFor, EachClassOfErrorCodeNamesItsBit) {
  EXPECT_EQ(errorRegisterBitFor(0x2310), kErrorCurrent);
  EXPECT_EQ(errorRegisterBitFor(0x3210), kErrorVoltage);
  EXPECT_EQ(errorRegisterBitFor(0x4210), kErrorTemperature);
  EXPECT_EQ(errorRegisterBitFor(0x8130), kErrorCommunication);
  EXPECT_EQ(errorRegisterBitFor(0x8210), kErrorCommunication);
  EXPECT_EQ(errorRegisterBitFor(0xFF01), kErrorManufacturer);
  for (const unsigned code :
       {0x0000U, 0x1000U, 0x5000U, 0x6100U, 0x7000U, 0x8400U, 0x8611U, 0x9000U}) {
    EXPECT_EQ(errorRegisterBitFor(static_cast<uint16_t>(code)), 0U) << std::hex << code;
  }
}

TEST_F(EmcyProducerTest, ARaisedConditionSendsCodeRegisterAndManufacturerBytes) {
  EXPECT_TRUE(emcy_.raise(0x2310, 0, kErrorCurrent, kManufacturer));
  EXPECT_EQ(clock_.next, kStart);  // due at once
  EXPECT_EQ(emcy_.nextDeadline(NmtState::kPreOperational), kStart);
  send();
  EXPECT_EQ(sent(), frames({emcy(0x2310, 0x03, kManufacturer)}));
  EXPECT_TRUE(emcy_.active(0x2310, 0));
  EXPECT_EQ(emcy_.errorRegister(), 0x03U);
  EXPECT_EQ(value(0x1001, 0), 0x03U);
  EXPECT_EQ(emcy_.nextDeadline(NmtState::kPreOperational), kNever);
}

TEST_F(EmcyProducerTest, RaisingAnActiveConditionAgainDoesNothing) {
  EXPECT_TRUE(emcy_.raise(0x8130, 1, kErrorCommunication));
  EXPECT_FALSE(emcy_.raise(0x8130, 1, kErrorCommunication));
  EXPECT_TRUE(emcy_.raise(0x8130, 2, kErrorCommunication));  // another source: its own condition
  send();
  EXPECT_EQ(sent(), frames({emcy(0x8130, 0x11), emcy(0x8130, 0x11)}));
  EXPECT_EQ(emcy_.activeCount(), 2U);
}

TEST_F(EmcyProducerTest, ClearingTheLastConditionSendsTheErrorResetFrame) {
  EXPECT_TRUE(emcy_.raise(0x2310, 0, kErrorCurrent));
  EXPECT_TRUE(emcy_.raise(0x4210, 0, kErrorTemperature));
  EXPECT_TRUE(emcy_.clear(0x2310, 0));
  EXPECT_EQ(value(0x1001, 0), 0x09U);  // generic and temperature remain
  EXPECT_TRUE(emcy_.clear(0x4210, 0));
  EXPECT_FALSE(emcy_.clear(0x4210, 0));  // not active any more
  EXPECT_EQ(value(0x1001, 0), 0U);
  send();
  EXPECT_EQ(sent(), frames({emcy(0x2310, 0x03), emcy(0x4210, 0x0B), emcy(0x0000, 0x00)}));
}

TEST_F(EmcyProducerTest, TheHistoryKeepsTheNewestFirstAndIsClearedByWritingZero) {
  emcy_.signal(0x1000, kErrorGeneric);
  emcy_.signal(0x2000, kErrorCurrent, kManufacturer);
  emcy_.signal(0x3000, kErrorVoltage);
  emcy_.signal(0x4000, kErrorTemperature);  // 0x1003 holds three: the oldest goes
  EXPECT_EQ(value(0x1003, 0), 3U);
  EXPECT_EQ(value(0x1003, 1), 0x4000U);
  EXPECT_EQ(value(0x1003, 2), 0x3000U);
  EXPECT_EQ(value(0x1003, 3), 0xA2A12000U);  // the first two manufacturer bytes above the code
  EXPECT_EQ(emcy_.activeCount(), 0U);        // events, not conditions
  EXPECT_EQ(write(emcy_, 0x1003, 0, 1, 1), AbortCode::kInvalidValue);
  EXPECT_EQ(write(emcy_, 0x1003, 1, 0, 4), AbortCode::kInvalidValue);
  EXPECT_EQ(value(0x1003, 0), 3U);
  EXPECT_EQ(write(emcy_, 0x1003, 0, 0, 1), AbortCode::kNone);
  for (uint8_t sub = 0; sub <= 3U; ++sub) {
    EXPECT_EQ(value(0x1003, sub), 0U) << unsigned{sub};
  }
}

TEST_F(EmcyProducerTest, NothingLeavesWhileStoppedOrInitialising) {
  EXPECT_TRUE(emcy_.raise(0x5000, 0, 0));
  send(NmtState::kStopped);
  send(NmtState::kInitialising);
  EXPECT_TRUE(sent().empty());
  EXPECT_EQ(emcy_.nextDeadline(NmtState::kStopped), kNever);
  send(NmtState::kOperational);  // it waited
  EXPECT_EQ(sent(), frames({emcy(0x5000, 0x01)}));
}

TEST_F(EmcyProducerTest, TheInhibitTimeSpacesFramesWithoutLosingThem) {
  store(0x1015, 0, 10);  // 1 ms
  emcy_.signal(0x1001, 0);
  emcy_.signal(0x1002, 0);
  send();
  EXPECT_EQ(sent(), frames({emcy(0x1001, 0x01)}));
  EXPECT_EQ(emcy_.nextDeadline(NmtState::kPreOperational), after(1000));
  emcy_.process(after(999), NmtState::kPreOperational, tx_);
  EXPECT_TRUE(sent().empty());
  emcy_.process(after(1000), NmtState::kPreOperational, tx_);
  EXPECT_EQ(sent(), frames({emcy(0x1002, 0x01)}));
  EXPECT_EQ(emcy_.lost(), 0U);
}

TEST_F(EmcyProducerTest, AFullQueueLosesTheNewestEmcyAndCountsIt) {
  for (uint16_t i = 0; i < kPending + 2U; ++i) {
    emcy_.signal(static_cast<uint16_t>(0xFF00U + i), 0);
  }
  EXPECT_EQ(emcy_.lost(), 2U);
  EXPECT_EQ(value(0x1003, 1), 0xFF04U);  // the history still records every one
  send();
  EXPECT_EQ(sent(), frames({emcy(0xFF00, 0x01), emcy(0xFF01, 0x01), emcy(0xFF02, 0x01)}));
}

TEST_F(EmcyProducerTest, AFullConditionTableStillSendsTheEmcyAndCountsIt) {
  EXPECT_TRUE(emcy_.raise(0x1001, 0, 0));
  EXPECT_TRUE(emcy_.raise(0x1002, 0, 0));
  EXPECT_FALSE(emcy_.raise(0x1003, 0, 0));
  EXPECT_EQ(emcy_.conditionsFull(), 1U);
  EXPECT_EQ(emcy_.activeCount(), 2U);
  EXPECT_FALSE(emcy_.active(0x1003, 0));
  EXPECT_FALSE(emcy_.clear(0x1003, 0));
  send();
  EXPECT_EQ(sent().size(), 3U);
}

TEST_F(EmcyProducerTest, AnInvalidEmcyCobIdProducesNothing) {
  store(0x1014, 0, 0x80000085U);
  EXPECT_TRUE(emcy_.raise(0x6100, 0, 0));
  send();
  store(0x1014, 0, 0x85U);
  send();  // what was pending while invalid is not produced later
  EXPECT_TRUE(sent().empty());
  EXPECT_EQ(emcy_.errorRegister(), 0x01U);  // the condition itself stands
}

TEST_F(EmcyProducerTest, TheCobIdChangesOnlyWhileInvalidAndNeverToARestrictedCanId) {
  EXPECT_EQ(write(emcy_, 0x1014, 0, 0x20000085U, 4), AbortCode::kInvalidValue);  // 29-bit
  EXPECT_EQ(write(emcy_, 0x1014, 0, 0x86U, 4), AbortCode::kInvalidValue);        // valid to valid
  EXPECT_EQ(write(emcy_, 0x1014, 0, 0x80000085U, 4), AbortCode::kNone);
  EXPECT_EQ(write(emcy_, 0x1014, 0, 0x701U, 4), AbortCode::kInvalidValue);  // error control
  EXPECT_EQ(write(emcy_, 0x1014, 0, 0x80000701U, 4), AbortCode::kNone);     // invalid: allowed
  EXPECT_EQ(write(emcy_, 0x1014, 0, 0x0A5U, 4), AbortCode::kNone);
  emcy_.signal(0x7000, 0);
  send();
  EXPECT_EQ(sent(), frames({emcy(0x7000, 0x01, nullptr, 0x0A5)}));
}

TEST_F(EmcyProducerTest, ResetCommunicationDropsPendingFramesAndKeepsConditions) {
  EXPECT_TRUE(emcy_.raise(0x2310, 0, kErrorCurrent));
  store(0x1001, 0, 0);  // as restoring the communication area's defaults does
  emcy_.onResetCommunication();
  send();
  EXPECT_TRUE(sent().empty());
  EXPECT_TRUE(emcy_.active(0x2310, 0));
  EXPECT_EQ(value(0x1001, 0), 0x03U);
}

TEST_F(EmcyProducerTest, TheProfileMovesTheRegisterToTheFourthByte) {
  profile_.layout = EmcyLayout::kErrorRegisterInFourthByte;
  EXPECT_TRUE(emcy_.raise(0x2310, 0, kErrorCurrent, kManufacturer));
  send();
  EXPECT_EQ(sent(), frames({frame(0x85, {0, 0, 0, 0x03, 0, 0, 0, 0})}));
}

TEST_F(EmcyProducerTest, TheProfileMayHideTheRegisterAndOmitTheErrorReset) {
  profile_.reportErrorRegister = false;
  profile_.errorResetFrame = false;
  EXPECT_TRUE(emcy_.raise(0x2310, 0, kErrorCurrent));
  EXPECT_EQ(value(0x1001, 0), 0U);
  EXPECT_EQ(emcy_.errorRegister(), 0U);
  EXPECT_TRUE(emcy_.clear(0x2310, 0));
  send();
  EXPECT_EQ(sent(), frames({emcy(0x2310, 0x00)}));
}

}  // namespace
}  // namespace costa::test
