// A TPDO that maps constants, through wire frames (host-tests/data/tpdo_constants.eds): 0x2000
// holds $NODEID+0x300, whose stored form lacks the node-id, so the TPDO reads it through the
// dictionary, which adds the node-id; 0x2001 (0x1234) is copied as it is stored. The same
// dictionary on two node-ids sends two different first entries and the same second one.
#include "dictionary_node_bus.hpp"
#include "in_process_bus.hpp"
#include "tpdo_constants_od.hpp"

namespace costa::test {
namespace {

using ConstantsBus = DictionaryNodeBus<gen::tpdo_constants::Values, gen::tpdo_constants::Capacity>;

NodeSettings withNodeId(uint8_t nodeId) {
  NodeSettings settings;
  settings.nodeId = nodeId;
  return settings;
}

TEST(TpdoConstants, TheNodeIdIsInTheConstantThatHoldsIt) {
  ConstantsBus bus(gen::tpdo_constants::kDefinition, withNodeId(1));
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    rx 601 [8] 40 00 20 00 00 00 00 00   # 0x2000 read by SDO: 0x301
    tx 581 [8] 43 00 20 00 01 03 00 00
    rx 000 [2] 01 00
    rx 080 [0]
    tx 181 [6] 01 03 00 00 34 12         # the same value, then 0x2001
  )",
                     bus),
            "");
}

TEST(TpdoConstants, AnotherNodeIdGivesAnotherValue) {
  ConstantsBus bus(gen::tpdo_constants::kDefinition, withNodeId(0x7F));
  EXPECT_EQ(playText(R"(
    tx 77F [1] 00
    rx 000 [2] 01 00
    rx 080 [0]
    tx 1FF [6] 7F 03 00 00 34 12         # 0x300 + 0x7F
    rx 080 [0]
    tx 1FF [6] 7F 03 00 00 34 12
  )",
                     bus),
            "");
}

// 0x2002 holds what 0x2001 holds, and a PDO may map it: a value of its own, not one copy of the
// two, so an application event on it is not one on TPDO1, which maps 0x2001.
TEST(TpdoConstants, AnEventOnAnEqualConstantIsNotAnEventOfTheTpdoMappingTheOther) {
  ConstantsBus bus(gen::tpdo_constants::kDefinition, withNodeId(1));
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    rx 601 [8] 2F 00 18 02 FE 00 00 00   # TPDO1 event-driven (type 254)
    tx 581 [8] 60 00 18 02 00 00 00 00
    rx 000 [2] 01 00
    silence
  )",
                     bus),
            "");
  bus.node().markChanged(0x2002, 0);
  bus.wait(1);
  EXPECT_EQ(playText("silence", bus), "");
  bus.node().markChanged(0x2001, 0);
  bus.wait(1);
  EXPECT_EQ(playText("tx 181 [6] 01 03 00 00 34 12", bus), "");
}

}  // namespace
}  // namespace costa::test
