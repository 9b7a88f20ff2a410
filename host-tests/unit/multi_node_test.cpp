// Several independent nodes in one program, on one in-memory bus.
#include <gtest/gtest.h>

#include "allocation_guard.hpp"
#include "costa/port/memory/memory_can_bus.hpp"
#include "example_target.hpp"
#include "frame_text.hpp"
#include "gefran_target.hpp"
#include "gra_od.hpp"

namespace costa::test {
namespace {

CanFrame frame(const char* text) {
  CanFrame result;
  std::string error;
  EXPECT_TRUE(host::parseFrame(text, &result, &error)) << error;
  return result;
}

std::string next(port::MemoryCanEndpoint& endpoint) {
  CanFrame received;
  return endpoint.receive(&received) ? host::formatFrame(received) : "nothing";
}

TEST(MultiNode, NodesShareABusAndAnswerOnlyForThemselves) {
  port::MemoryCanBus bus;
  port::MemoryCanEndpoint client;
  port::MemoryCanEndpoint portA;
  port::MemoryCanEndpoint portB;
  bus.attach(client);
  bus.attach(portA);
  bus.attach(portB);
  example::ExampleTarget nodeA(portA, DeviceConfig{5, true, nullptr, nullptr});
  example::ExampleTarget nodeB(portB, DeviceConfig{9, true, nullptr, nullptr});
  const auto deliver = [&](Microseconds now) {
    NoAllocationScope scope;
    CanFrame received;
    while (portA.receive(&received)) {
      nodeA.onFrame(received, now);
    }
    while (portB.receive(&received)) {
      nodeB.onFrame(received, now);
    }
  };
  {
    NoAllocationScope scope;
    nodeA.start(0);
    nodeB.start(0);
  }
  EXPECT_EQ(next(client), "705 [1] 00");
  EXPECT_EQ(next(client), "709 [1] 00");
  deliver(0);  // the nodes see each other's boot-up and ignore it

  client.tryTransmit(frame("605 [8] 2B 17 10 00 0A 00 00 00"));  // node 5: heartbeat 10 ms
  client.tryTransmit(frame("609 [8] 40 00 12 01 00 00 00 00"));  // node 9: its SDO COB-ID
  deliver(1000);
  EXPECT_EQ(next(client), "585 [8] 60 17 10 00 00 00 00 00");
  EXPECT_EQ(next(client), "589 [8] 43 00 12 01 09 06 00 00");
  EXPECT_EQ(nodeA.node().dictionary().readUnsigned(0x1017, 0, 0), 10U);
  EXPECT_EQ(nodeB.node().dictionary().readUnsigned(0x1017, 0, 0), 0U);

  client.tryTransmit(frame("000 [2] 01 00"));  // start all
  deliver(2000);
  EXPECT_EQ(nodeA.node().state(), NmtState::kOperational);
  EXPECT_EQ(nodeB.node().state(), NmtState::kOperational);
  client.tryTransmit(frame("000 [2] 02 09"));  // stop node 9 only
  deliver(3000);
  EXPECT_EQ(nodeA.node().state(), NmtState::kOperational);
  EXPECT_EQ(nodeB.node().state(), NmtState::kStopped);
  {
    NoAllocationScope scope;
    nodeA.process(11000);
    nodeB.process(11000);
  }
  EXPECT_EQ(next(client), "705 [1] 05");
  EXPECT_EQ(next(client), "nothing");
}

TEST(MultiNode, NodesWithDifferentDictionariesAnswerEachWithItsOwn) {
  port::MemoryCanBus bus;
  port::MemoryCanEndpoint client;
  port::MemoryCanEndpoint examplePort;
  port::MemoryCanEndpoint sensorPort;
  bus.attach(client);
  bus.attach(examplePort);
  bus.attach(sensorPort);
  example::ExampleTarget example(examplePort, DeviceConfig{5, true, nullptr, nullptr});
  gefran::GraTarget sensor(sensorPort, DeviceConfig{9, true, nullptr, nullptr});
  const auto deliver = [&](Microseconds now) {
    NoAllocationScope scope;
    CanFrame received;
    while (examplePort.receive(&received)) {
      example.onFrame(received, now);
    }
    while (sensorPort.receive(&received)) {
      sensor.onFrame(received, now);
    }
  };
  {
    NoAllocationScope scope;
    example.start(0);
    sensor.start(0);
  }
  EXPECT_EQ(next(client), "705 [1] 00");
  EXPECT_EQ(next(client), "709 [1] 00");
  EXPECT_EQ(next(client), "189 [8] 00 00 00 00 FF FF FF 00");  // the sensor starts by itself
  deliver(0);

  // The same request to both: each answers from its own dictionary.
  client.tryTransmit(frame("605 [8] 40 08 10 00 00 00 00 00"));  // 0x1008 device name
  client.tryTransmit(frame("609 [8] 40 08 10 00 00 00 00 00"));
  deliver(1000);
  EXPECT_EQ(next(client), "585 [8] 41 08 10 00 0D 00 00 00");  // 13 bytes, segmented
  EXPECT_EQ(next(client), "589 [8] 47 08 10 00 47 52 41 00");  // "GRA", expedited
  client.tryTransmit(frame("605 [8] 60 00 00 00 00 00 00 00"));
  deliver(1000);
  EXPECT_EQ(next(client), "585 [8] 00 43 6F 73 74 61 20 65");  // "Costa e"
  client.tryTransmit(frame("605 [8] 70 00 00 00 00 00 00 00"));
  deliver(1000);
  EXPECT_EQ(next(client), "585 [8] 13 78 61 6D 70 6C 65 00");    // "xample"
  client.tryTransmit(frame("605 [8] 40 18 10 01 00 00 00 00"));  // 0x1018:01 vendor-ID
  client.tryTransmit(frame("609 [8] 40 18 10 01 00 00 00 00"));
  deliver(2000);
  EXPECT_EQ(next(client), "585 [8] 43 18 10 01 05 0C 00 00");
  EXPECT_EQ(next(client), "589 [8] 43 18 10 01 93 00 00 00");
  // An object only one of them has.
  client.tryTransmit(frame("605 [8] 40 10 21 00 00 00 00 00"));
  client.tryTransmit(frame("609 [8] 40 10 21 00 00 00 00 00"));
  deliver(3000);
  EXPECT_EQ(next(client), "585 [8] 80 10 21 00 00 00 02 06");  // 0x06020000 no such object
  EXPECT_EQ(next(client), "589 [8] 4F 10 21 00 07 00 00 00");
  EXPECT_EQ(next(client), "nothing");
}

}  // namespace
}  // namespace costa::test
