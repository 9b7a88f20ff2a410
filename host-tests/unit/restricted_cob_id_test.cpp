// CiA 301 7.3.5: the restricted CAN-IDs (NMT 0x000, 0x001-0x07F, 0x101-0x180, SDO 0x581-0x5FF
// and 0x601-0x67F, 0x6E0-0x6FF, NMT error control 0x701-0x77F, 0x780-0x7FF with LSS) are not
// for the configurable SYNC and EMCY objects: a write giving one aborts with 0x06090030.
// Found with the fuzz harness (docs/fuzzing.md): an EMCY on 0x000 went out as an NMT command,
// and a SYNC consumer on 0x601 swallowed the node's own SDO requests.
#include "example_fixture.hpp"

namespace costa::test {
namespace {

using RestrictedCobIds = ExampleNodeTest;

TEST_F(RestrictedCobIds, EmcyCannotBeMadeValidOnARestrictedCanId) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 14 10 00 00 00 00 80   # not valid: any CAN-ID may be kept
    tx 581 [8] 60 14 10 00 00 00 00 00
    rx 601 [8] 23 14 10 00 00 00 00 00   # valid on 0x000 (NMT)
    tx 581 [8] 80 14 10 00 30 00 09 06
    rx 601 [8] 23 14 10 00 85 05 00 00   # 0x585: the SDO responses of node 5
    tx 581 [8] 80 14 10 00 30 00 09 06
    rx 601 [8] 23 14 10 00 05 07 00 00   # 0x705: the heartbeat of node 5
    tx 581 [8] 80 14 10 00 30 00 09 06
    rx 601 [8] 23 14 10 00 E4 07 00 00   # 0x7E4: LSS responses
    tx 581 [8] 80 14 10 00 30 00 09 06
    rx 601 [8] 23 14 10 00 7F 00 00 00   # 0x07F: high-priority range
    tx 581 [8] 80 14 10 00 30 00 09 06
    rx 601 [8] 40 14 10 00 00 00 00 00   # the refused writes changed nothing
    tx 581 [8] 43 14 10 00 00 00 00 80
    rx 601 [8] 23 14 10 00 95 00 00 00   # 0x095 is free
    tx 581 [8] 60 14 10 00 00 00 00 00
  )");
  withNode([](Node& node) { node.raiseError(0x5000, 0); });
  EXPECT_TRANSCRIPT("tx 095 [8] 00 50 01 00 00 00 00 00");
}

TEST_F(RestrictedCobIds, SyncCannotUseARestrictedCanId) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 05 10 00 01 06 00 00   # consumer on 0x601: this node's SDO requests
    tx 581 [8] 80 05 10 00 30 00 09 06
    rx 601 [8] 23 05 10 00 00 00 00 40   # producer on 0x000 (NMT)
    tx 581 [8] 80 05 10 00 30 00 09 06
    rx 601 [8] 23 05 10 00 02 07 00 40   # producer on 0x702: the heartbeat of node 2
    tx 581 [8] 80 05 10 00 30 00 09 06
    rx 601 [8] 40 05 10 00 00 00 00 00   # still the consumer on 0x080, and SDO still works
    tx 581 [8] 43 05 10 00 80 00 00 00
    rx 601 [8] 23 05 10 00 90 00 00 00   # 0x090 is free
    tx 581 [8] 60 05 10 00 00 00 00 00
  )");
}

}  // namespace
}  // namespace costa::test
