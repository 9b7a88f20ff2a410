// The SRDO mapping's length rule through wire frames (CiA 304): at most 8 bytes of normal data,
// each mapped with its inverted copy. The example cannot show it: its SRDO mapping objects hold
// two pairs, and its one entry longer than 4 bytes (0x2004:05) cannot be mapped by an RPDO,
// which a mapping written while its SRDO has no direction must allow (0x06040041 answers).
// host-tests/data/srdo_long.eds has three pairs (0x1381:01..06) and 0x2000, an UNSIGNED32.
// SRDO 1 is not valid (direction 0), so its mapping may be written.
#include "dictionary_node_bus.hpp"
#include "in_process_bus.hpp"
#include "srdo_long_od.hpp"

namespace costa::test {
namespace {

using SrdoLongBus = DictionaryNodeBus<gen::srdo_long::Values, gen::srdo_long::Capacity>;

NodeSettings nodeOne() {
  NodeSettings settings;
  settings.nodeId = 1;
  return settings;
}

TEST(SrdoMappingLength, MoreThanEightBytesOfNormalDataAreRefused) {
  SrdoLongBus bus(gen::srdo_long::kDefinition, nodeOne());
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    rx 601 [8] 23 81 13 01 20 00 00 20   # three pairs of 0x2000 (32 bits): 12 bytes
    tx 581 [8] 60 81 13 01 00 00 00 00
    rx 601 [8] 23 81 13 02 20 00 00 20
    tx 581 [8] 60 81 13 02 00 00 00 00
    rx 601 [8] 23 81 13 03 20 00 00 20
    tx 581 [8] 60 81 13 03 00 00 00 00
    rx 601 [8] 23 81 13 04 20 00 00 20
    tx 581 [8] 60 81 13 04 00 00 00 00
    rx 601 [8] 23 81 13 05 20 00 00 20
    tx 581 [8] 60 81 13 05 00 00 00 00
    rx 601 [8] 23 81 13 06 20 00 00 20
    tx 581 [8] 60 81 13 06 00 00 00 00
    rx 601 [8] 2F 81 13 00 06 00 00 00   # all three: longer than a frame
    tx 581 [8] 80 81 13 00 42 00 04 06
    rx 601 [8] 40 81 13 00 00 00 00 00   # the mapping stays disabled
    tx 581 [8] 4F 81 13 00 00 00 00 00
    rx 601 [8] 2F 81 13 00 04 00 00 00   # two: 8 bytes, the most
    tx 581 [8] 60 81 13 00 00 00 00 00
    rx 601 [8] 40 81 13 00 00 00 00 00
    tx 581 [8] 4F 81 13 00 04 00 00 00
  )",
                     bus),
            "");
}

}  // namespace
}  // namespace costa::test
