// The losses costa-slave shows: the node's and the socket's counters, as one line.
#include "slave_counters.hpp"
#include "example_fixture.hpp"

namespace costa::test {
namespace {

using host::countersOf;
using host::describeCounters;
using host::SlaveCounters;

using SlaveCountersTest = ExampleNodeTest;

TEST_F(SlaveCountersTest, NothingLostAtStart) {
  const SlaveCounters counters = countersOf(bus_.node(), port::SocketCanPort::Counters{});
  EXPECT_EQ(describeCounters(counters),
            "tx dropped 0, tx expired 0, EMCY lost 0, error frames 0, rx overruns 0, bus-offs 0");
  EXPECT_EQ(counters, SlaveCounters{});
}

TEST_F(SlaveCountersTest, DropsOfTheNodeAndErrorFramesOfTheSocket) {
  withNode([](Node& node) { node.onControllerEvent(CanControllerEvent::kRxOverrun, node.now()); });
  EXPECT_TRANSCRIPT("tx 081 [8] 10 81 11 00 00 00 00 00");
  withNode([](Node& node) {
    node.onControllerEvent(CanControllerEvent::kBusOff, node.now());
    for (uint16_t i = 1; i <= 10; ++i) {  // 8 fit the EMCY queue; they wait for the bus
      node.signalError(static_cast<uint16_t>(0xFF00U + i), kErrorManufacturer);
    }
  });
  for (int i = 0; i < 40; ++i) {
    EXPECT_TRANSCRIPT("rx 601 [8] 40 00 20 00 00 00 00 00");
  }
  port::SocketCanPort::Counters socket;
  socket.errorFrames = 3;
  socket.refused = 7;  // retried by the node: not a loss
  const SlaveCounters counters = countersOf(bus_.node(), socket);
  // 8 EMCY and 40 answers for the frames of the transmit queue.
  static_assert(DefaultNodeCapacity::kTxQueueDepth == 8U, "the dropped count below");
  EXPECT_EQ(describeCounters(counters),
            "tx dropped 40, tx expired 0, EMCY lost 2, error frames 3, rx overruns 1, bus-offs 1");
  SlaveCounters other = counters;
  other.errorFrames = 4;
  EXPECT_NE(counters, other);
}

TEST(ControllerEventNames, EveryEventHasItsName) {
  EXPECT_STREQ(host::controllerEventName(CanControllerEvent::kRxOverrun), "rx overrun");
  EXPECT_STREQ(host::controllerEventName(CanControllerEvent::kErrorPassive), "error passive");
  EXPECT_STREQ(host::controllerEventName(CanControllerEvent::kErrorActive), "error active");
  EXPECT_STREQ(host::controllerEventName(CanControllerEvent::kBusOff), "bus-off");
  EXPECT_STREQ(host::controllerEventName(CanControllerEvent::kBusOffRecovered),
               "bus-off recovered");
}

}  // namespace
}  // namespace costa::test
