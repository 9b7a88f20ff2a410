// A ParameterStore over the example dictionary and an in-memory medium, with helpers that load
// into a freshly reset dictionary (as a node does after a reset) and locate slots by the
// documented layout (docs/storage.md).
#pragma once

#include <gtest/gtest.h>

#include <vector>

#include "costa/parameter_store.hpp"
#include "costa/port/memory/memory_storage.hpp"
#include "dictionary_instance.hpp"
#include "example_od.hpp"

namespace costa::test {

using ExampleDictionary = DictionaryInstance<gen::example::Values>;

inline constexpr uint8_t kCommunication = od::kGroupCommunication;
inline constexpr uint8_t kApplication = od::kGroupApplication;

class ExampleStoreTest : public ::testing::Test {
 protected:
  ExampleStoreTest() : store_(device_.dictionary, storage_) {}
  void SetUp() override { ASSERT_TRUE(store_.layOut()); }

  struct Loaded {
    StoreResult result;
    std::vector<uint8_t> bytes;  ///< The group's values after the load.
  };

  /// Loads `group` into a dictionary fresh from its defaults, through a new store over the same
  /// medium: what the next boot would see.
  Loaded loadFresh(uint8_t group, const od::Definition& definition = gen::example::kDefinition) {
    ExampleDictionary fresh(definition);
    ParameterStore store(fresh.dictionary, storage_);
    if (!store.layOut()) {
      return {StoreResult::kNotLaidOut, {}};
    }
    const StoreResult result = store.load(group);
    return {result, groupBytes(fresh.dictionary, group)};
  }

  static std::vector<uint8_t> defaults(uint8_t group) {
    ExampleDictionary fresh(gen::example::kDefinition);
    return groupBytes(fresh.dictionary, group);
  }
  static std::vector<uint8_t> pattern(uint8_t group, unsigned seed) {
    ExampleDictionary dictionary(gen::example::kDefinition);
    fillGroup(dictionary.dictionary, group, seed);
    return groupBytes(dictionary.dictionary, group);
  }
  /// Fills the device's group with pattern `seed` and saves it.
  StoreResult savePattern(uint8_t group, unsigned seed) {
    fillGroup(device_.dictionary, group, seed);
    return store_.save(group);
  }

  /// Slot layout as documented: groups in ascending order, two slots of header + payload each.
  size_t slotSize(uint8_t group) const { return kImageHeaderSize + defaults(group).size(); }
  size_t slotOffset(uint8_t group, size_t slot) const {
    size_t offset = 0;
    for (unsigned g = 1; g < group; ++g) {
      if (store_.hasGroup(static_cast<uint8_t>(g))) {
        offset += 2U * slotSize(static_cast<uint8_t>(g));
      }
    }
    return offset + slot * slotSize(group);
  }
  SlotInfo slot(uint8_t group, size_t index) {
    return inspectSlot(storage_, slotOffset(group, index), slotSize(group));
  }

  port::MemoryStorageOf<4096> storage_;
  ExampleDictionary device_{gen::example::kDefinition};
  ParameterStore store_;
};

}  // namespace costa::test
