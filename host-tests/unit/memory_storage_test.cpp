// The in-memory EEPROM model: reads, writes, erases, range checks, counters, power loss.
#include <gtest/gtest.h>

#include <vector>

#include "costa/port/memory/memory_storage.hpp"

namespace costa::port {
namespace {

std::vector<uint8_t> contents(const MemoryStorage& storage) {
  return std::vector<uint8_t>(storage.bytes(), storage.bytes() + storage.size());
}

TEST(MemoryStorageTest, StartsErasedAndKeepsWrittenBytes) {
  MemoryStorageOf<8> storage;
  EXPECT_EQ(storage.size(), 8U);
  EXPECT_EQ(contents(storage), std::vector<uint8_t>(8, 0xFF));
  const uint8_t data[3] = {1, 2, 3};
  EXPECT_TRUE(storage.write(2, data, 3));
  uint8_t back[8] = {};
  EXPECT_TRUE(storage.read(0, back, 8));
  EXPECT_EQ(std::vector<uint8_t>(back, back + 8),
            (std::vector<uint8_t>{0xFF, 0xFF, 1, 2, 3, 0xFF, 0xFF, 0xFF}));
  EXPECT_TRUE(storage.erase(3, 1));
  EXPECT_EQ(contents(storage), (std::vector<uint8_t>{0xFF, 0xFF, 1, 0xFF, 3, 0xFF, 0xFF, 0xFF}));
}

TEST(MemoryStorageTest, UsesACallerBufferAsItIs) {
  uint8_t buffer[4] = {9, 8, 7, 6};
  MemoryStorage storage(buffer, sizeof(buffer));
  uint8_t back[4] = {};
  EXPECT_TRUE(storage.read(0, back, 4));
  EXPECT_EQ(back[0], 9U);
  EXPECT_EQ(back[3], 6U);
  const uint8_t value = 0x55;
  EXPECT_TRUE(storage.write(1, &value, 1));
  EXPECT_EQ(buffer[1], 0x55U);
}

TEST(MemoryStorageTest, RefusesAccessOutsideTheMediumWithoutCounting) {
  MemoryStorageOf<8> storage;
  uint8_t data[9] = {};
  EXPECT_FALSE(storage.read(0, data, 9));
  EXPECT_FALSE(storage.read(9, data, 0));
  EXPECT_FALSE(storage.write(7, data, 2));
  EXPECT_FALSE(storage.write(SIZE_MAX, data, 2));
  EXPECT_FALSE(storage.erase(4, SIZE_MAX));
  EXPECT_TRUE(storage.read(8, data, 0));
  EXPECT_EQ(storage.modifyingCalls(), 0U);
  EXPECT_EQ(contents(storage), std::vector<uint8_t>(8, 0xFF));
}

TEST(MemoryStorageTest, CountsWritesErasesAndCommits) {
  MemoryStorageOf<16> storage;
  const uint8_t data[5] = {};
  EXPECT_TRUE(storage.write(0, data, 5));
  EXPECT_TRUE(storage.write(8, data, 2));
  EXPECT_TRUE(storage.erase(0, 16));
  EXPECT_TRUE(storage.commit());
  EXPECT_EQ(storage.bytesWritten(), 7U);
  EXPECT_EQ(storage.writeCalls(), 2U);
  EXPECT_EQ(storage.bytesErased(), 16U);
  EXPECT_EQ(storage.eraseCalls(), 1U);
  EXPECT_EQ(storage.commits(), 1U);
  EXPECT_EQ(storage.modifyingCalls(), 4U);
  uint8_t back[16];
  EXPECT_TRUE(storage.read(0, back, 16));
  EXPECT_EQ(storage.modifyingCalls(), 4U);
  storage.resetCounters();
  EXPECT_EQ(storage.bytesWritten(), 0U);
  EXPECT_EQ(storage.bytesErased(), 0U);
  EXPECT_EQ(storage.modifyingCalls(), 0U);
}

TEST(MemoryStorageTest, ACutWriteAppliesOnlyTheBytesBeforeTheCut) {
  MemoryStorageOf<8> storage;
  const uint8_t first[2] = {0x11, 0x22};
  const uint8_t second[4] = {0xA1, 0xA2, 0xA3, 0xA4};
  storage.cutPowerAfter(4);
  EXPECT_TRUE(storage.write(0, first, 2));
  EXPECT_TRUE(storage.powered());
  EXPECT_FALSE(storage.write(3, second, 4));
  EXPECT_FALSE(storage.powered());
  EXPECT_EQ(contents(storage),
            (std::vector<uint8_t>{0x11, 0x22, 0xFF, 0xA1, 0xA2, 0xFF, 0xFF, 0xFF}));
  EXPECT_EQ(storage.bytesWritten(), 4U);
}

TEST(MemoryStorageTest, AfterTheCutEverythingButReadsFailsUntilPowerReturns) {
  MemoryStorageOf<8> storage;
  const uint8_t data[2] = {1, 2};
  storage.cutPowerAfter(0);
  EXPECT_FALSE(storage.write(0, data, 2));
  EXPECT_EQ(contents(storage), std::vector<uint8_t>(8, 0xFF));
  EXPECT_FALSE(storage.write(0, data, 1));
  EXPECT_FALSE(storage.erase(0, 1));
  EXPECT_FALSE(storage.commit());
  uint8_t back[2] = {};
  EXPECT_TRUE(storage.read(0, back, 2));
  EXPECT_EQ(storage.writeCalls(), 1U);  // only the write that was cut
  EXPECT_EQ(storage.commits(), 0U);
  storage.restorePower();
  EXPECT_TRUE(storage.powered());
  EXPECT_TRUE(storage.write(0, data, 2));
  EXPECT_TRUE(storage.commit());
  EXPECT_EQ(storage.bytes()[1], 2U);
}

TEST(MemoryStorageTest, AnOperationThatUsesTheLastBytesOfTheBudgetCompletes) {
  MemoryStorageOf<8> storage;
  const uint8_t data[3] = {1, 2, 3};
  storage.cutPowerAfter(3);
  EXPECT_TRUE(storage.write(0, data, 3));
  EXPECT_TRUE(storage.commit());
  EXPECT_TRUE(storage.write(3, data, 0));
  EXPECT_FALSE(storage.write(3, data, 1));
  EXPECT_EQ(storage.bytes()[3], 0xFFU);
}

TEST(MemoryStorageTest, EraseCountsAgainstTheBudgetAndIsCutInAscendingOrder) {
  MemoryStorageOf<8> storage;
  const uint8_t zeros[8] = {};
  EXPECT_TRUE(storage.write(0, zeros, 8));
  storage.cutPowerAfter(3);
  EXPECT_FALSE(storage.erase(1, 6));
  EXPECT_EQ(contents(storage), (std::vector<uint8_t>{0, 0xFF, 0xFF, 0xFF, 0, 0, 0, 0}));
  EXPECT_EQ(storage.bytesErased(), 3U);
}

TEST(MemoryStorageTest, RestoringPowerDisarmsAPendingCut) {
  MemoryStorageOf<8> storage;
  const uint8_t data[8] = {};
  storage.cutPowerAfter(1);
  storage.restorePower();
  EXPECT_TRUE(storage.write(0, data, 8));
  EXPECT_TRUE(storage.powered());
}

}  // namespace
}  // namespace costa::port
