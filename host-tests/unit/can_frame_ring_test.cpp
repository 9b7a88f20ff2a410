// CanFrameRing: order, a full ring, the overrun report, and one producer and one consumer
// thread running at once without a frame lost, doubled or torn.
#include <gtest/gtest.h>

#include <thread>

#include "costa/port/can_frame_ring.hpp"

namespace costa::test {
namespace {

CanFrame numbered(uint32_t n) {
  CanFrame frame;
  frame.id = n & 0x7FFU;
  frame.dlc = 8;
  for (size_t i = 0; i < 4; ++i) {  // the number twice: a torn copy shows as two halves
    frame.data[i] = static_cast<uint8_t>(n >> (8U * i));
    frame.data[4U + i] = frame.data[i];
  }
  return frame;
}

uint32_t numberOf(const CanFrame& frame) {
  uint32_t n = 0;
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(frame.data[i], frame.data[4U + i]);
    n |= uint32_t{frame.data[i]} << (8U * i);
  }
  return n;
}

TEST(CanFrameRing, GivesFramesBackInTheOrderTheyCame) {
  port::CanFrameRing<4> ring;
  CanFrame out;
  EXPECT_TRUE(ring.empty());
  EXPECT_FALSE(ring.pop(&out));
  for (uint32_t round = 0; round < 3; ++round) {  // the indices pass the end of the slots
    EXPECT_TRUE(ring.push(numbered(10U * round)));
    EXPECT_TRUE(ring.push(numbered(10U * round + 1U)));
    EXPECT_TRUE(ring.push(numbered(10U * round + 2U)));
    EXPECT_FALSE(ring.empty());
    ASSERT_TRUE(ring.pop(&out));
    EXPECT_TRUE(sameOnWire(out, numbered(10U * round)));
    ASSERT_TRUE(ring.pop(&out));
    EXPECT_TRUE(sameOnWire(out, numbered(10U * round + 1U)));
    ASSERT_TRUE(ring.pop(&out));
    EXPECT_TRUE(sameOnWire(out, numbered(10U * round + 2U)));
    EXPECT_FALSE(ring.pop(&out));
  }
  EXPECT_FALSE(ring.takeOverrun());
  EXPECT_EQ(ring.dropped(), 0U);
}

TEST(CanFrameRing, AFullRingDropsTheNewFrameAndReportsOneOverrun) {
  port::CanFrameRing<2> ring;
  EXPECT_TRUE(ring.push(numbered(1)));
  EXPECT_TRUE(ring.push(numbered(2)));
  EXPECT_FALSE(ring.push(numbered(3)));
  EXPECT_FALSE(ring.push(numbered(4)));
  EXPECT_EQ(ring.dropped(), 2U);
  EXPECT_TRUE(ring.takeOverrun());
  EXPECT_FALSE(ring.takeOverrun());  // reported once
  CanFrame out;
  ASSERT_TRUE(ring.pop(&out));
  EXPECT_TRUE(sameOnWire(out, numbered(1)));  // what was in stays, in order
  ASSERT_TRUE(ring.pop(&out));
  EXPECT_TRUE(sameOnWire(out, numbered(2)));
  EXPECT_FALSE(ring.pop(&out));
  EXPECT_TRUE(ring.push(numbered(5)));  // room again
  EXPECT_FALSE(ring.takeOverrun());
}

TEST(CanFrameRing, AProducerAndAConsumerThreadLoseNothing) {
  constexpr uint32_t kFrames = 200000;
  static port::CanFrameRing<8> ring;  // small: both sides meet full and empty often
  uint32_t refused = 0;               // pushes into a full ring (the producer then tries again)
  std::thread producer([&refused] {
    for (uint32_t n = 0; n < kFrames; ++n) {
      while (!ring.push(numbered(n))) {
        ++refused;
        std::this_thread::yield();
      }
    }
  });
  uint32_t expected = 0;
  CanFrame out;
  while (expected < kFrames) {
    if (ring.pop(&out)) {
      ASSERT_EQ(numberOf(out), expected);
      ASSERT_EQ(out.id, expected & 0x7FFU);
      ++expected;
    } else {
      std::this_thread::yield();
    }
  }
  producer.join();
  EXPECT_FALSE(ring.pop(&out));
  EXPECT_EQ(ring.dropped(), refused);  // each refused push counted, no other
}

}  // namespace
}  // namespace costa::test
