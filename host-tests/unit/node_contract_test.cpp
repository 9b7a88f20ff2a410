// The node's fault contract through wire frames: several listeners hear the same events, an RPDO
// is applied whole or not at all, and what does not fit (hooks, listeners, error conditions, a
// mapping) is refused and counted, never silently lost.
// Example RPDO2: COB-ID 0x301, maps 0x2004:03 (INTEGER32), 0x2005:01 and 0x2005:02 (UNSIGNED16).
#include <algorithm>
#include <ostream>
#include <vector>

#include "costa/od/little_endian.hpp"
#include "dictionary_node_bus.hpp"
#include "example_fixture.hpp"
#include "example_od.hpp"

namespace costa::test {
namespace {

using NodeContract = ExampleNodeTest;

/// One event a listener heard: what, and its two arguments.
struct Heard {
  char what;  // n: NMT state change, w: RPDO writing, r: RPDO received, s: SYNC, c: reset comm.
  unsigned first;
  unsigned second;
  bool operator==(const Heard& other) const {
    return what == other.what && first == other.first && second == other.second;
  }
};

std::ostream& operator<<(std::ostream& out, const Heard& heard) {
  return out << heard.what << ' ' << std::hex << heard.first << ' ' << heard.second;
}

/// Keeps the events it hears in a fixed array (the node calls it where nothing may allocate).
class EventLog : public NodeEvents {
 public:
  void onNmtStateChanged(NmtState previous, NmtState current) noexcept override {
    add('n', static_cast<unsigned>(previous), static_cast<unsigned>(current));
  }
  void onRpdoWriting(uint16_t index) noexcept override { add('w', index, 0); }
  void onRpdoReceived(uint16_t index) noexcept override { add('r', index, 0); }
  void onSync(uint8_t counter) noexcept override { add('s', counter, 0); }
  void onResetCommunication() noexcept override { add('c', 0, 0); }

  std::vector<Heard> heard() const { return {events_, events_ + count_}; }

 private:
  void add(char what, unsigned first, unsigned second) {
    if (count_ < kCapacity) {
      events_[count_++] = Heard{what, first, second};
    }
  }
  static constexpr size_t kCapacity = 16;
  Heard events_[kCapacity] = {};
  size_t count_ = 0;
};

TEST_F(NodeContract, TwoListenersHearTheSameEventsInTheSameOrder) {
  EventLog profileLayer;
  EventLog application;
  ASSERT_TRUE(bus_.node().addListener(profileLayer));
  ASSERT_TRUE(bus_.node().addListener(application));
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 01
    rx 301 [8] 01 00 00 00 02 00 03 00
    rx 080 [0]
    rx 000 [2] 82 01
    tx 701 [1] 00
  )");
  const std::vector<Heard> expected = {{'n', 0x7F, 0x05}, {'w', 0x1401, 0},  {'r', 0x1401, 0},
                                       {'s', 0, 0},       {'n', 0x05, 0x00}, {'c', 0, 0},
                                       {'n', 0x00, 0x7F}};
  EXPECT_EQ(profileLayer.heard(), expected);
  EXPECT_EQ(application.heard(), expected);
}

/// Refuses 0x2005:02 = 0xBAD, as a device whose values need more than limits: in check() (the
/// RPDO's first phase) and in write() (an SDO download).
class RefusingTable : public ObjectHook {
 public:
  AbortCode check(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override {
    ++checks;
    if (ref.subIndex() == 2U && length == 2U && loadU16(data) == 0x0BADU) {
      return AbortCode::kInvalidValue;
    }
    return dictionary.check(ref, data, length);
  }
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override {
    const AbortCode verdict = check(dictionary, ref, data, length);
    if (verdict != AbortCode::kNone) {
      return verdict;
    }
    ++writes;
    return dictionary.write(ref, data, length);
  }
  int checks = 0;
  int writes = 0;
};

TEST_F(NodeContract, AnRpdoWithARefusedEntryWritesNothingAndIsCounted) {
  RefusingTable hook;
  EventLog events;
  ASSERT_TRUE(bus_.node().attachHook(0x2005, 0x2005, hook));
  ASSERT_TRUE(bus_.node().addListener(events));
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 01
    rx 301 [8] 11 00 00 00 22 00 AD 0B   # 0x2005:02 = 0x0BAD: refused by the hook
    silence
  )");
  // The first entry, before the refused one, is not written.
  EXPECT_EQ(static_cast<int64_t>(value(0x2004, 3)), -100000);
  EXPECT_EQ(value(0x2005, 1), 0x1234U);
  EXPECT_EQ(value(0x2005, 2), 0x1234U);
  EXPECT_EQ(hook.writes, 0);
  EXPECT_EQ(bus_.node().statistics().rpdosRefused, 1U);
  const std::vector<Heard> started = {{'n', 0x7F, 0x05}};
  EXPECT_EQ(events.heard(), started);  // no writing, no received

  EXPECT_TRANSCRIPT("rx 301 [8] 11 00 00 00 22 00 33 00");  // accepted: every entry written
  EXPECT_EQ(value(0x2004, 3), 0x11U);
  EXPECT_EQ(value(0x2005, 1), 0x22U);
  EXPECT_EQ(value(0x2005, 2), 0x33U);
  EXPECT_EQ(hook.writes, 2);
  EXPECT_EQ(bus_.node().statistics().rpdosRefused, 1U);
  const std::vector<Heard> applied = {{'n', 0x7F, 0x05}, {'w', 0x1401, 0}, {'r', 0x1401, 0}};
  EXPECT_EQ(events.heard(), applied);
}

TEST_F(NodeContract, TheSameValueBySdoIsAbortedWithTheHooksCode) {
  RefusingTable hook;
  ASSERT_TRUE(bus_.node().attachHook(0x2005, 0x2005, hook));
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 05 20 02 AD 0B 00 00
    tx 581 [8] 80 05 20 02 30 00 09 06
  )");
  EXPECT_EQ(value(0x2005, 2), 0x1234U);
}

/// Writes every value, then refuses 0x2005:02 = 0xBAD: a hook that finds out too late (after it
/// changed the value), which its check() could not see coming.
class LateRefusal : public ObjectHook {
 public:
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override {
    const AbortCode written = dictionary.write(ref, data, length);
    if (ref.subIndex() == 2U && length == 2U && loadU16(data) == 0x0BADU) {
      return AbortCode::kCannotStoreState;
    }
    return written;
  }
};

TEST_F(NodeContract, ARefusalAtWriteRestoresEveryEntryAnEntryMappedTwiceAndTheRefusingOneToo) {
  LateRefusal hook;
  ASSERT_TRUE(bus_.node().attachHook(0x2005, 0x2005, hook));
  // RPDO2 remapped: 0x2005:01 twice, then 0x2005:02.
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 01 14 01 01 03 00 80
    tx 581 [8] 60 01 14 01 00 00 00 00
    rx 601 [8] 2F 01 16 00 00 00 00 00
    tx 581 [8] 60 01 16 00 00 00 00 00
    rx 601 [8] 23 01 16 01 10 01 05 20
    tx 581 [8] 60 01 16 01 00 00 00 00
    rx 601 [8] 23 01 16 02 10 01 05 20
    tx 581 [8] 60 01 16 02 00 00 00 00
    rx 601 [8] 23 01 16 03 10 02 05 20
    tx 581 [8] 60 01 16 03 00 00 00 00
    rx 601 [8] 2F 01 16 00 03 00 00 00
    tx 581 [8] 60 01 16 00 00 00 00 00
    rx 601 [8] 23 01 14 01 01 03 00 00
    tx 581 [8] 60 01 14 01 00 00 00 00
    rx 000 [2] 01 01
    rx 301 [6] 11 11 22 22 AD 0B   # 0x2005:01 = 0x1111, then 0x2222; 0x2005:02 refused late
    silence
  )");
  EXPECT_EQ(value(0x2005, 1), 0x1234U);  // its own value, not the first entry's 0x1111
  EXPECT_EQ(value(0x2005, 2), 0x1234U);  // the hook had written 0x0BAD before it refused
  EXPECT_EQ(bus_.node().statistics().rpdosRefused, 1U);
  EXPECT_TRANSCRIPT("rx 301 [6] 11 11 22 22 33 00");  // accepted: the later entry wins
  EXPECT_EQ(value(0x2005, 1), 0x2222U);
  EXPECT_EQ(value(0x2005, 2), 0x33U);
}

class Silent : public ObjectHook {};
class Quiet : public NodeEvents {};

TEST_F(NodeContract, HooksBeyondTheTableAreRefusedAndCounted) {
  // The example device holds 4 of the 8 places; 4 more fit.
  Silent hooks[5];
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(bus_.node().attachHook(0x3000, 0x3000, hooks[i])) << i;
  }
  EXPECT_EQ(bus_.node().statistics().hooksRefused, 0U);
  EXPECT_FALSE(bus_.node().attachHook(0x3000, 0x3000, hooks[4]));
  EXPECT_EQ(bus_.node().statistics().hooksRefused, 1U);
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 17 10 00 00 00 00 00   # the node goes on as before
    tx 581 [8] 4B 17 10 00 00 00 00 00
  )");
}

TEST_F(NodeContract, ListenersBeyondTheCapacityOrTwiceAreRefusedAndCounted) {
  Quiet listeners[4];  // the example device is the first of NodeListeners::kCapacity
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(bus_.node().addListener(listeners[i])) << i;
  }
  EXPECT_FALSE(bus_.node().addListener(listeners[3]));
  EXPECT_FALSE(bus_.node().addListener(listeners[0]));
  EXPECT_EQ(bus_.node().statistics().listenersRefused, 2U);
}

TEST_F(NodeContract, AnErrorBeyondTheConditionTableStillSendsItsEmcyAndIsCounted) {
  // DefaultNodeCapacity::kEmcyConditions = 8 conditions.
  withNode([](Node& node) {
    for (uint16_t i = 0; i < 8; ++i) {
      EXPECT_TRUE(node.raiseError(static_cast<uint16_t>(0xFF00U + i), 0x80)) << i;
    }
  });
  EXPECT_EQ(bus_.node().statistics().emcyConditionsFull, 0U);
  std::string sent;
  for (int i = 0; i < 8; ++i) {
    sent += "tx 081 [8] 0" + std::to_string(i) + " FF 81 00 00 00 00 00\n";
  }
  EXPECT_EQ(play(sent), "");
  withNode([](Node& node) { EXPECT_FALSE(node.raiseError(0xFF08, 0x80)); });
  EXPECT_TRANSCRIPT(R"(
    tx 081 [8] 08 FF 81 00 00 00 00 00   # sent, though not remembered
    rx 601 [8] 40 03 10 00 00 00 00 00   # 0x1003 holds it too (8 places, all taken)
    tx 581 [8] 4F 03 10 00 08 00 00 00
    rx 601 [8] 40 03 10 01 00 00 00 00   # the newest first
    tx 581 [8] 43 03 10 01 08 FF 00 00
  )");
  EXPECT_EQ(bus_.node().statistics().emcyConditionsFull, 1U);
  withNode([](Node& node) {
    EXPECT_FALSE(node.clearError(0xFF08));  // never active: nothing to clear
    for (uint16_t i = 0; i < 8; ++i) {
      EXPECT_TRUE(node.clearError(static_cast<uint16_t>(0xFF00U + i))) << i;
    }
  });
  EXPECT_TRANSCRIPT("tx 081 [8] 00 00 00 00 00 00 00 00");
}

/// The example's dictionary with a PDO's mapping default (`mappingIndex`:`subIndex`, whose
/// default is `original`) changed to `mapping`: a definition whose default cannot be resolved,
/// as a stored or generated table could hold one that no SDO write would accept.
class PatchedExample {
 public:
  PatchedExample(uint16_t mappingIndex, uint8_t subIndex, uint32_t original, uint32_t mapping)
      : definition_(gen::example::kDefinition) {
    gen::example::Values values{};
    const od::ObjectDictionary dictionary(gen::example::kDefinition, &values);
    const size_t offset = dictionary.find(mappingIndex, subIndex).offset();
    defaults_.assign(definition_.defaults, definition_.defaults + definition_.defaultCount);
    // The patched record gets bytes of its own (the mapping value has bits 16..28, which only
    // bytes hold), after a copy of every record's.
    size_t end = 0;
    for (const od::DefaultValue& value : defaults_) {
      if ((value.flags & od::kDefaultInBytes) != 0U) {
        end = std::max<size_t>(end, value.value + value.size);
      }
    }
    bytes_.assign(definition_.defaultBytes, definition_.defaultBytes + end);
    bool patched = false;
    for (od::DefaultValue& value : defaults_) {
      if (value.offset == offset) {
        EXPECT_EQ(value.size, 4U);
        if ((value.flags & od::kDefaultInBytes) != 0U) {
          EXPECT_EQ(loadU32(definition_.defaultBytes + value.value), original);
        } else {  // held as itself: bits 0..15 and 29..31
          EXPECT_EQ(value.value + ((value.flags & od::kDefaultTopBits) << 24U), original);
        }
        value.flags = od::kDefaultInBytes | od::kDefaultNumber;
        value.size = 4;
        value.value = static_cast<uint16_t>(bytes_.size());
        for (unsigned i = 0; i < 4U; ++i) {
          bytes_.push_back(static_cast<uint8_t>(mapping >> (8U * i)));
        }
        patched = true;
      }
    }
    EXPECT_TRUE(patched);
    definition_.defaults = defaults_.data();
    definition_.defaultBytes = bytes_.data();
  }
  const od::Definition& definition() const { return definition_; }

 private:
  od::Definition definition_;
  std::vector<od::DefaultValue> defaults_;
  std::vector<uint8_t> bytes_;
};

using ExampleDictionaryBus = DictionaryNodeBus<gen::example::Values, gen::example::Capacity>;

/// The example, node-id 1, powered on over a PatchedExample (same arguments).
class PatchedExampleNode {
 public:
  PatchedExampleNode(uint16_t mappingIndex, uint8_t subIndex, uint32_t original, uint32_t mapping)
      : patched_(mappingIndex, subIndex, original, mapping),
        bus_(patched_.definition(), settings()) {}
  ExampleDictionaryBus& bus() { return bus_; }
  uint32_t unresolvableMappings() { return bus_.node().statistics().unresolvableMappings; }

 private:
  static NodeSettings settings() {
    NodeSettings s;
    s.nodeId = 1;
    return s;
  }
  PatchedExample patched_;
  ExampleDictionaryBus bus_;
};

TEST(NodeContractMapping, AnUnresolvableMappingEmptiesThePdoAndIsCounted) {
  PatchedExampleNode patched(0x1600, 1, 0x20000020, 0x30000020);  // 0x3000 does not exist
  ExampleDictionaryBus& bus = patched.bus();
  EXPECT_EQ(patched.unresolvableMappings(), 1U);
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    rx 601 [8] 40 00 16 01 00 00 00 00   # the mapping reads as configured
    tx 581 [8] 43 00 16 01 20 00 00 30
    rx 000 [2] 01 01
    rx 201 [5] 10 27 00 00 F6            # the PDO maps nothing: longer than its 0 bytes
    tx 081 [8] 20 82 11 00 00 00 00 00
  )",
                     bus),
            "");
  EXPECT_EQ(bus.node().dictionary().readUnsigned(0x2000, 0, 0), 1000U);
  // The master repairs the mapping: the PDO works. Every configuration of the PDO while its
  // mapping could not be resolved counted once (the invalidation configures it again).
  EXPECT_EQ(playText(R"(
    rx 601 [8] 23 00 14 01 01 02 00 80   # invalidate RPDO1
    tx 581 [8] 60 00 14 01 00 00 00 00
    tx 081 [8] 00 00 00 00 00 00 00 00   # configured again: its length error no longer applies
    rx 601 [8] 2F 00 16 00 00 00 00 00
    tx 581 [8] 60 00 16 00 00 00 00 00
    rx 601 [8] 23 00 16 01 20 00 00 20
    tx 581 [8] 60 00 16 01 00 00 00 00
    rx 601 [8] 2F 00 16 00 02 00 00 00
    tx 581 [8] 60 00 16 00 00 00 00 00
    rx 601 [8] 23 00 14 01 01 02 00 00
    tx 581 [8] 60 00 14 01 00 00 00 00
    rx 201 [5] 10 27 00 00 F6            # the right length: no EMCY
    silence
  )",
                     bus),
            "");
  EXPECT_EQ(bus.node().dictionary().readUnsigned(0x2000, 0, 0), 10000U);
  EXPECT_EQ(patched.unresolvableMappings(), 2U);
}

TEST(NodeContractMapping, AnUnresolvableTpdoMappingEmptiesThePdoAndIsCounted) {
  // TPDO1 (0x181) maps 0x2001:00 (UNSIGNED32) and 0x2011:00 (INTEGER16).
  // Its second entry cannot be resolved: the PDO maps neither, not the first alone.
  PatchedExampleNode patched(0x1A00, 2, 0x20110010, 0x30000010);  // 0x3000 does not exist
  ExampleDictionaryBus& bus = patched.bus();
  EXPECT_EQ(patched.unresolvableMappings(), 1U);
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    rx 601 [8] 40 00 1A 02 00 00 00 00   # the mapping reads as configured
    tx 581 [8] 43 00 1A 02 10 00 00 30
    rx 601 [8] 2F 00 18 02 01 00 00 00   # TPDO1 at every SYNC
    tx 581 [8] 60 00 18 02 00 00 00 00
    rx 000 [2] 01 01
    rx 080 [0]                           # SYNC: the PDO is empty, as one that maps nothing
    tx 181 [0]
  )",
                     bus),
            "");
  EXPECT_EQ(patched.unresolvableMappings(), 2U);  // at the reset and at the type's write
  // The master repairs the mapping: TPDO1 sends its six bytes. Every configuration of the PDO
  // while its mapping could not be resolved counted once: at the reset, at the write of its
  // transmission type and at its invalidation.
  EXPECT_EQ(playText(R"(
    rx 601 [8] 23 00 18 01 81 01 00 80   # invalidate TPDO1
    tx 581 [8] 60 00 18 01 00 00 00 00
    rx 601 [8] 2F 00 1A 00 00 00 00 00
    tx 581 [8] 60 00 1A 00 00 00 00 00
    rx 601 [8] 23 00 1A 02 10 00 11 20
    tx 581 [8] 60 00 1A 02 00 00 00 00
    rx 601 [8] 2F 00 1A 00 02 00 00 00
    tx 581 [8] 60 00 1A 00 00 00 00 00
    rx 601 [8] 23 00 18 01 81 01 00 00
    tx 581 [8] 60 00 18 01 00 00 00 00
    rx 080 [0]
    tx 181 [6] xx xx xx xx xx xx         # uptime (seconds), temperature
  )",
                     bus),
            "");
  EXPECT_EQ(patched.unresolvableMappings(), 3U);
}

}  // namespace
}  // namespace costa::test
