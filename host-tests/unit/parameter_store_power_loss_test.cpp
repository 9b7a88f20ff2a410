// Power loss at every byte of a save or an invalidate: afterwards a fresh dictionary loads
// exactly the complete old set or the complete new set, and the store keeps working.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "parameter_store_fixture.hpp"

namespace costa::test {
namespace {

/// Bytes programmed or erased by one operation on a medium prepared by `prepare`.
template <typename Prepare, typename Operate>
size_t bytesProgrammed(Prepare prepare, Operate operate) {
  port::MemoryStorageOf<4096> storage;
  ExampleDictionary device(gen::example::kDefinition);
  ParameterStore store(device.dictionary, storage);
  EXPECT_TRUE(store.layOut());
  prepare(device, store);
  storage.resetCounters();
  EXPECT_EQ(operate(device, store), StoreResult::kOk);
  return storage.bytesWritten() + storage.bytesErased();
}

struct Outcome {
  StoreResult operation;
  StoreResult load;
  std::vector<uint8_t> bytes;
  bool recovers;  ///< A further save and load worked.
};

/// Prepares a medium, cuts the power after `cut` bytes of `operate`, restores it, loads the
/// group into a fresh dictionary, then checks that a further save and load work.
template <typename Prepare, typename Operate>
Outcome cutDuring(size_t cut, uint8_t group, Prepare prepare, Operate operate) {
  port::MemoryStorageOf<4096> storage;
  ExampleDictionary device(gen::example::kDefinition);
  ParameterStore store(device.dictionary, storage);
  EXPECT_TRUE(store.layOut());
  prepare(device, store);
  storage.cutPowerAfter(cut);
  Outcome outcome{};
  outcome.operation = operate(device, store);
  storage.restorePower();

  ExampleDictionary rebooted(gen::example::kDefinition);
  ParameterStore reloaded(rebooted.dictionary, storage);
  EXPECT_TRUE(reloaded.layOut());
  outcome.load = reloaded.load(group);
  outcome.bytes = groupBytes(rebooted.dictionary, group);

  fillGroup(rebooted.dictionary, group, 200);
  ExampleDictionary again(gen::example::kDefinition);
  ParameterStore third(again.dictionary, storage);
  outcome.recovers = reloaded.save(group) == StoreResult::kOk && third.layOut() &&
                     third.load(group) == StoreResult::kOk &&
                     groupBytes(again.dictionary, group) == groupBytes(rebooted.dictionary, group);
  return outcome;
}

std::vector<uint8_t> patternOf(uint8_t group, unsigned seed) {
  ExampleDictionary dictionary(gen::example::kDefinition);
  fillGroup(dictionary.dictionary, group, seed);
  return groupBytes(dictionary.dictionary, group);
}

std::vector<uint8_t> defaultsOf(uint8_t group) {
  ExampleDictionary dictionary(gen::example::kDefinition);
  return groupBytes(dictionary.dictionary, group);
}

/// Saves pattern `seed` of `group`.
auto saveSeed(uint8_t group, unsigned seed) {
  return [group, seed](ExampleDictionary& device, ParameterStore& store) {
    fillGroup(device.dictionary, group, seed);
    return store.save(group);
  };
}

/// Checks every cut point of `operate` after `prepare`: the old set (`oldResult`, `oldBytes`)
/// until the last byte, the new set once every byte is programmed.
template <typename Prepare, typename Operate>
void checkEveryCut(uint8_t group, Prepare prepare, Operate operate, StoreResult oldResult,
                   const std::vector<uint8_t>& oldBytes, StoreResult newResult,
                   const std::vector<uint8_t>& newBytes) {
  const size_t total = bytesProgrammed(prepare, operate);
  ASSERT_GT(total, kImageHeaderSize);
  for (size_t cut = 0; cut <= total; ++cut) {
    const Outcome outcome = cutDuring(cut, group, prepare, operate);
    const bool complete = cut == total;
    EXPECT_EQ(outcome.operation == StoreResult::kOk, complete) << "cut after " << cut;
    EXPECT_EQ(outcome.load, complete ? newResult : oldResult) << "cut after " << cut;
    EXPECT_EQ(outcome.bytes, complete ? newBytes : oldBytes) << "cut after " << cut;
    EXPECT_TRUE(outcome.recovers) << "cut after " << cut;
  }
}

TEST(ParameterStorePowerLossTest, TheFirstSaveYieldsTheDefaultsOrTheNewSet) {
  const auto nothing = [](ExampleDictionary&, ParameterStore&) {};
  checkEveryCut(kApplication, nothing, saveSeed(kApplication, 2), StoreResult::kNoImage,
                defaultsOf(kApplication), StoreResult::kOk, patternOf(kApplication, 2));
}

TEST(ParameterStorePowerLossTest, ASaveOverOneImageYieldsTheOldOrTheNewSet) {
  const auto oneImage = [](ExampleDictionary& device, ParameterStore& store) {
    EXPECT_EQ(saveSeed(kApplication, 1)(device, store), StoreResult::kOk);
  };
  checkEveryCut(kApplication, oneImage, saveSeed(kApplication, 2), StoreResult::kOk,
                patternOf(kApplication, 1), StoreResult::kOk, patternOf(kApplication, 2));
}

TEST(ParameterStorePowerLossTest, ASaveOverTwoImagesNeverBringsBackTheOldest) {
  const auto twoImages = [](ExampleDictionary& device, ParameterStore& store) {
    EXPECT_EQ(saveSeed(kApplication, 1)(device, store), StoreResult::kOk);
    EXPECT_EQ(saveSeed(kApplication, 2)(device, store), StoreResult::kOk);
  };
  checkEveryCut(kApplication, twoImages, saveSeed(kApplication, 3), StoreResult::kOk,
                patternOf(kApplication, 2), StoreResult::kOk, patternOf(kApplication, 3));
}

TEST(ParameterStorePowerLossTest, ASmallGroupBehavesTheSame) {
  const auto twoImages = [](ExampleDictionary& device, ParameterStore& store) {
    EXPECT_EQ(saveSeed(kCommunication, 1)(device, store), StoreResult::kOk);
    EXPECT_EQ(saveSeed(kCommunication, 2)(device, store), StoreResult::kOk);
  };
  checkEveryCut(kCommunication, twoImages, saveSeed(kCommunication, 3), StoreResult::kOk,
                patternOf(kCommunication, 2), StoreResult::kOk, patternOf(kCommunication, 3));
}

TEST(ParameterStorePowerLossTest, InvalidateYieldsTheOldSetOrTheDefaults) {
  const auto twoImages = [](ExampleDictionary& device, ParameterStore& store) {
    EXPECT_EQ(saveSeed(kApplication, 1)(device, store), StoreResult::kOk);
    EXPECT_EQ(saveSeed(kApplication, 2)(device, store), StoreResult::kOk);
  };
  const auto invalidate = [](ExampleDictionary&, ParameterStore& store) {
    return store.invalidate(kApplication);
  };
  checkEveryCut(kApplication, twoImages, invalidate, StoreResult::kOk, patternOf(kApplication, 2),
                StoreResult::kNoImage, defaultsOf(kApplication));
}

TEST(ParameterStorePowerLossTest, ASaveAfterInvalidateYieldsTheDefaultsOrTheNewSet) {
  const auto invalidated = [](ExampleDictionary& device, ParameterStore& store) {
    EXPECT_EQ(saveSeed(kApplication, 1)(device, store), StoreResult::kOk);
    EXPECT_EQ(store.invalidate(kApplication), StoreResult::kOk);
  };
  checkEveryCut(kApplication, invalidated, saveSeed(kApplication, 2), StoreResult::kNoImage,
                defaultsOf(kApplication), StoreResult::kOk, patternOf(kApplication, 2));
}

TEST(ParameterStorePowerLossTest, ACutInOneGroupLeavesTheOtherGroupAlone) {
  port::MemoryStorageOf<4096> storage;
  ExampleDictionary device(gen::example::kDefinition);
  ParameterStore store(device.dictionary, storage);
  ASSERT_TRUE(store.layOut());
  fillGroup(device.dictionary, kCommunication, 4);
  ASSERT_EQ(store.save(kCommunication), StoreResult::kOk);
  fillGroup(device.dictionary, kApplication, 5);
  for (size_t cut = 0; cut < 150U; cut += 7U) {
    storage.cutPowerAfter(cut);
    EXPECT_NE(store.save(kApplication), StoreResult::kOk);
    storage.restorePower();
    ExampleDictionary rebooted(gen::example::kDefinition);
    ParameterStore reloaded(rebooted.dictionary, storage);
    ASSERT_TRUE(reloaded.layOut());
    EXPECT_EQ(reloaded.load(kCommunication), StoreResult::kOk);
    EXPECT_EQ(groupBytes(rebooted.dictionary, kCommunication), patternOf(kCommunication, 4));
  }
}

TEST(ParameterStorePowerLossTest, RandomCutsAcrossManyOperationsKeepTheLastCompletedOne) {
  port::MemoryStorageOf<4096> storage;
  ExampleDictionary device(gen::example::kDefinition);
  ParameterStore store(device.dictionary, storage);
  ASSERT_TRUE(store.layOut());
  std::mt19937 random(20240611U);
  StoreResult expectedResult = StoreResult::kNoImage;
  std::vector<uint8_t> expected = defaultsOf(kApplication);
  for (unsigned step = 1; step <= 300U; ++step) {
    const bool invalidating = random() % 5U == 0U;
    const unsigned seed = step % 200U;
    storage.cutPowerAfter(random() % 300U);
    StoreResult result;
    if (invalidating) {
      result = store.invalidate(kApplication);
    } else {
      fillGroup(device.dictionary, kApplication, seed);
      result = store.save(kApplication);
    }
    storage.restorePower();
    if (result == StoreResult::kOk) {
      expectedResult = invalidating ? StoreResult::kNoImage : StoreResult::kOk;
      expected = invalidating ? defaultsOf(kApplication) : patternOf(kApplication, seed);
    }
    ExampleDictionary rebooted(gen::example::kDefinition);
    ParameterStore reloaded(rebooted.dictionary, storage);
    ASSERT_TRUE(reloaded.layOut());
    ASSERT_EQ(reloaded.load(kApplication), expectedResult) << "step " << step;
    ASSERT_EQ(groupBytes(rebooted.dictionary, kApplication), expected) << "step " << step;
  }
}

}  // namespace
}  // namespace costa::test
