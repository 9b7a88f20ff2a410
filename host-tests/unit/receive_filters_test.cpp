// Node::receiveFilters(): the CAN-IDs a port programs into its controller's acceptance
// filters, and receiveFiltersVersion(), which says when to program them again. Checked through
// wire frames: every frame the filters turn away is one the node ignores.
// Example node-id 1: SYNC 0x080, EMCY of nodes 2 and 3 consumed (0x1028), TIME 0x100, RPDO1/2
// 0x201/0x301 and TPDO1/2 0x181/0x281 valid (RPDO3/4 and TPDO3/4 are not, by default), SDO 0x601,
// LSS 0x7E5 (the example has LSS).
#include <algorithm>
#include <vector>

#include "example_fixture.hpp"

namespace costa::test {
namespace {

using ReceiveFilters = ExampleNodeTest;

std::vector<CanIdFilter> filtersOf(Node& node) {
  std::vector<CanIdFilter> filters(64);
  filters.resize(node.receiveFilters(filters.data(), filters.size()));
  return filters;
}

std::vector<uint32_t> exactIds(const std::vector<CanIdFilter>& filters) {
  std::vector<uint32_t> ids;
  for (const CanIdFilter& filter : filters) {
    if (filter.mask == CanIdFilter::kExact) {
      ids.push_back(filter.id);
    }
  }
  return ids;
}

bool passes(const std::vector<CanIdFilter>& filters, uint32_t id) {
  for (const CanIdFilter& filter : filters) {
    if (filter.accepts(id)) {
      return true;
    }
  }
  return false;
}

TEST_F(ReceiveFilters, ListEveryServiceCanIdOnceInOrderThenTheErrorControlRange) {
  const std::vector<CanIdFilter> filters = filtersOf(bus_.node());
  const std::vector<uint32_t> expected = {0x000, 0x001, 0x080, 0x082, 0x083, 0x100, 0x103,
                                          0x104, 0x181, 0x201, 0x281, 0x301, 0x601, 0x7E5};
  EXPECT_EQ(exactIds(filters), expected);
  ASSERT_EQ(filters.size(), expected.size() + 1U);
  EXPECT_EQ(filters.back().id, 0x700U);
  EXPECT_EQ(filters.back().mask, 0x780U);
}

TEST_F(ReceiveFilters, EveryFrameTurnedAwayIsOneTheNodeIgnores) {
  const std::vector<CanIdFilter> filters = filtersOf(bus_.node());
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 00
  )");  // operational: RPDOs and remote requests are used too
  for (uint32_t id = 0; id <= 0x7FF; ++id) {
    if (passes(filters, id)) {
      continue;
    }
    for (bool rtr : {false, true}) {
      CanFrame frame;
      frame.id = id;
      frame.dlc = 8;
      frame.rtr = rtr;
      const uint32_t ignored = bus_.node().statistics().framesIgnored;
      bus_.node().onFrame(frame, bus_.node().now());
      EXPECT_EQ(bus_.node().statistics().framesIgnored, ignored + 1U)
          << "the node used a frame its filters turn away: " << std::hex << id;
    }
  }
  bus_.advance(0);
  EXPECT_EQ(bus_.unread(), 0U) << "the node answered a frame its filters turn away";
}

TEST_F(ReceiveFilters, AnRpdoCobIdWrittenChangesTheVersionAndTheList) {
  const uint32_t programmed = bus_.node().receiveFiltersVersion();
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 00 14 01 01 02 00 80   # RPDO1 not valid
    tx 581 [8] 60 00 14 01 00 00 00 00
  )");
  EXPECT_NE(bus_.node().receiveFiltersVersion(), programmed);
  std::vector<uint32_t> ids = exactIds(filtersOf(bus_.node()));
  EXPECT_EQ(std::count(ids.begin(), ids.end(), 0x201U), 0);

  const uint32_t second = bus_.node().receiveFiltersVersion();
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 00 14 01 22 02 00 00   # valid again, on 0x222
    tx 581 [8] 60 00 14 01 00 00 00 00
    rx 601 [8] 40 00 10 00 00 00 00 00   # a read changes nothing
    tx 581 [8] 43 00 10 00 00 00 00 00
  )");
  EXPECT_NE(bus_.node().receiveFiltersVersion(), second);
  ids = exactIds(filtersOf(bus_.node()));
  EXPECT_EQ(std::count(ids.begin(), ids.end(), 0x222U), 1);
  const uint32_t third = bus_.node().receiveFiltersVersion();
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 00 10 00 00 00 00 00
    tx 581 [8] 43 00 10 00 00 00 00 00
  )");
  EXPECT_EQ(bus_.node().receiveFiltersVersion(), third);
}

TEST_F(ReceiveFilters, ResetCommunicationChangesTheVersion) {
  const uint32_t programmed = bus_.node().receiveFiltersVersion();
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 82 01
    tx 701 [1] 00
  )");
  EXPECT_NE(bus_.node().receiveFiltersVersion(), programmed);
}

TEST_F(ReceiveFilters, ASmallerTableGetsWhatFitsAndTheTrueCount) {
  CanIdFilter filters[3] = {};
  CanIdFilter untouched;
  untouched.id = 0x123;
  filters[2] = untouched;
  EXPECT_EQ(bus_.node().receiveFilters(filters, 2), 15U);
  EXPECT_EQ(filters[0].id, 0x000U);
  EXPECT_EQ(filters[1].id, 0x001U);  // GFC
  EXPECT_EQ(filters[2].id, 0x123U);  // untouched
  EXPECT_EQ(bus_.node().receiveFilters(nullptr, 0), 15U);
}

}  // namespace
}  // namespace costa::test
