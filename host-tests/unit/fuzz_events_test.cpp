// The fuzz input encoding (host-tests/fuzz/fuzz_events.hpp, docs/fuzzing.md), byte by byte,
// and whole inputs run through the fuzz session.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fuzz_events.hpp"
#include "fuzz_session.hpp"
#include "fuzzed_device.hpp"

namespace costa::fuzz {
namespace {

/// The events of `input`; a simulation event's text points into `input`, which must outlive them.
std::vector<Event> decode(const std::vector<uint8_t>& input) {
  EventReader reader(input.data(), input.size());
  std::vector<Event> events;
  Event event;
  while (reader.next(&event)) {
    events.push_back(event);
  }
  return events;
}

TEST(FuzzEvents, HeaderChoosesTheNodeId) {
  EXPECT_EQ(decodeHeader(0).nodeId, 0U);
  EXPECT_FALSE(decodeHeader(0).explicitId);
  EXPECT_EQ(decodeHeader(5).nodeId, 5U);
  EXPECT_TRUE(decodeHeader(5).explicitId);
  EXPECT_EQ(decodeHeader(127).nodeId, 127U);
  EXPECT_EQ(decodeHeader(128).nodeId, 0xFFU);
  EXPECT_EQ(decodeHeader(255).nodeId, 0xFFU);
  EXPECT_TRUE(decodeHeader(200).explicitId);
  EXPECT_EQ(EventReader(nullptr, 0).header(), 0U);
  EXPECT_TRUE(decode({}).empty());
  EXPECT_TRUE(decode({0x01}).empty());
}

TEST(FuzzEvents, Frames) {
  const std::vector<Event> events = decode({
      0x01, 0x02, 0x01, 0x06, 0x01, 0x00,  // header 1; 11-bit 0x601, DLC 2
      0x0C, 0xFF, 0xFF, 1,    2,    3,
      4,    5,    6,    7,    8,           // DLC 12 (8 data bytes), id masked to 0x7FF
      0x18, 0x01, 0x07,                    // remote frame 0x701, DLC 8, no data
      0x21, 0x78, 0x56, 0x34, 0xF2, 0xAA,  // 29-bit 0x12345678, DLC 1
  });
  ASSERT_EQ(events.size(), 4U);
  EXPECT_EQ(events[0].kind, EventKind::kFrame);
  EXPECT_EQ(events[0].frame.id, 0x601U);
  EXPECT_EQ(events[0].frame.dlc, 2U);
  EXPECT_EQ(events[0].frame.data[0], 0x01U);
  EXPECT_EQ(events[1].frame.id, 0x7FFU);
  EXPECT_EQ(events[1].frame.dlc, 12U);
  EXPECT_EQ(events[1].frame.data[7], 8U);
  EXPECT_TRUE(events[2].frame.rtr);
  EXPECT_EQ(events[2].frame.id, 0x701U);
  EXPECT_EQ(events[2].frame.dlc, 8U);
  EXPECT_TRUE(events[3].frame.extended);
  EXPECT_EQ(events[3].frame.id, 0x12345678U);
  EXPECT_EQ(events[3].frame.data[0], 0xAAU);
}

TEST(FuzzEvents, TimeControllerPowerAndSimulation) {
  const std::vector<uint8_t> input = {
      0x00, 0x40, 200,  0x41, 0xE8, 0x03, 0x42, 3,    0x43, 0x44, 0x45, 0x7F,  // waits
      0x80, 0x81, 0x82, 0x86, 0x87, 0x88, 0x10, 0x00,                          // controller, power
      0x89, 0x09, 'a',  'n',  'g',  'l',  'e',  ' ',  '2',  '7',  '0',         // sim angle 270
      0x8A, 0x8D, 0xBF,                                                        // nothing
      0xC3, 0x40, 0x00, 0x10, 0x00, 0x00, 0x00, 0x00, 0x00,                    // own SDO request
  };
  const std::vector<Event> events = decode(input);
  ASSERT_EQ(events.size(), 18U);
  EXPECT_EQ(events[0].duration, 200U);
  EXPECT_EQ(events[1].duration, 1000000U);
  EXPECT_EQ(events[2].duration, 3000000U);
  EXPECT_EQ(events[3].kind, EventKind::kWaitForDeadline);
  EXPECT_EQ(events[3].duration, 0U);
  EXPECT_EQ(events[4].duration, 1U);
  EXPECT_EQ(events[5].duration, 1000U);
  EXPECT_EQ(events[6].duration, 59000U);
  EXPECT_EQ(events[7].kind, EventKind::kRefuseFrames);
  EXPECT_EQ(events[8].kind, EventKind::kAcceptFrames);
  EXPECT_EQ(events[9].kind, EventKind::kControllerEvent);
  EXPECT_EQ(events[9].code, 0U);   // rx overrun
  EXPECT_EQ(events[10].code, 4U);  // bus-off recovered
  EXPECT_EQ(events[11].kind, EventKind::kPowerCycle);
  EXPECT_EQ(events[12].kind, EventKind::kStoragePowerCut);
  EXPECT_EQ(events[12].bytes, 16U);
  EXPECT_EQ(events[13].kind, EventKind::kSimulate);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(events[13].text), events[13].textLength),
            "angle 270");
  EXPECT_EQ(events[14].kind, EventKind::kNothing);
  EXPECT_EQ(events[15].kind, EventKind::kNothing);
  EXPECT_EQ(events[16].kind, EventKind::kNothing);
  EXPECT_EQ(events[17].kind, EventKind::kOwnSdoRequest);
  EXPECT_EQ(events[17].frame.dlc, 8U);
  EXPECT_EQ(events[17].frame.data[0], 0x40U);
  EXPECT_EQ(events[17].frame.data[2], 0x10U);
}

TEST(FuzzEvents, SdoToAnEntryByItsNumber) {
  const std::vector<Event> events = decode({0x00, 0x8B, 7, 0x8C, 200, 1, 2, 3, 4, 0x8C, 1});
  ASSERT_EQ(events.size(), 2U);
  EXPECT_EQ(events[0].kind, EventKind::kEntryUpload);
  EXPECT_EQ(events[0].code, 7U);
  EXPECT_EQ(events[1].kind, EventKind::kEntryDownload);
  EXPECT_EQ(events[1].code, 200U);
  EXPECT_EQ(events[1].frame.data[3], 4U);
}

TEST(FuzzEvents, APayloadCutShortEndsTheInput) {
  EXPECT_EQ(decode({0x00, 0x08, 0x01, 0x06, 1, 2, 3}).size(), 0U);
  EXPECT_EQ(decode({0x00, 0x87, 0x41, 0x01}).size(), 1U);
  EXPECT_EQ(decode({0x00, 0xC0, 1, 2, 3, 4, 5, 6, 7}).size(), 0U);
  EXPECT_EQ(decode({0x00, 0x89}).size(), 0U);
  EXPECT_EQ(decode({0x00, 0x89, 0x05, 'r', 'a', 'w'}).size(), 0U);
  EXPECT_EQ(decode({0x00, 0x89, 0x00}).size(), 1U);  // an empty command
}

TEST(FuzzSession, RunsEveryDeviceAndReportsUnknownOnes) {
  // Header 0, SDO upload of 0x1000 to the node's own server, NMT start all, a simulation
  // command (a device without it refuses it), 2 s.
  const std::vector<uint8_t> input = {0x00, 0xC0, 0x40, 0x00, 0x10, 0x00, 0x00, 0x00, 0x00,
                                      0x00, 0x02, 0x00, 0x00, 0x01, 0x00, 0x89, 0x09, 'a',
                                      'n',  'g',  'l',  'e',  ' ',  '9',  '0',  0x42, 0x02};
  ASSERT_FALSE(fuzzedDeviceNames().empty());
  for (const std::string& device : fuzzedDeviceNames()) {
    EXPECT_EQ(runFuzzInput(device, input.data(), input.size()), "") << device;
  }
  EXPECT_EQ(runFuzzInput("toaster", input.data(), input.size()), "unknown device 'toaster'");
}

TEST(FuzzSession, ASimulationCommandGoesToTheDevicesControl) {
  // GRA, node-id 2: the shaft at 270 degrees, then 100 ms for the cyclic TPDO with both angles;
  // a command the sensor refuses, and one sent to the example, which has none, change nothing.
  const std::vector<uint8_t> input = {0x02, 0x89, 0x09, 'a',  'n',  'g',  'l',  'e', ' ', '2',
                                      '7',  '0',  0x41, 0x64, 0x00, 0x89, 0x02, 'n', 'o', 0x00};
  std::string trace;
  EXPECT_EQ(runFuzzInput("gra", input.data(), input.size(), &trace), "") << trace;
  EXPECT_NE(trace.find("event 1 sim angle 270\n"), std::string::npos) << trace;
  EXPECT_NE(trace.find("  tx 182 [8] 0A 8C 03 84 FF FF FF 00\n"), std::string::npos) << trace;
  EXPECT_NE(trace.find("event 3 sim no\n  = refused: unknown command 'no' (raw, angle, fault)\n"),
            std::string::npos)
      << trace;
  trace.clear();
  EXPECT_EQ(runFuzzInput("example", input.data(), input.size(), &trace), "") << trace;
  EXPECT_NE(trace.find("  = refused: this device has no simulation commands\n"), std::string::npos)
      << trace;
}

TEST(FuzzSession, EntryNumbersWrapAroundTheDictionary) {
  std::string trace;
  // Entry 0 of the example is 0x1000:00; 255 wraps to some entry, both are answered.
  const std::vector<uint8_t> input = {0x00, 0x8B, 0, 0x8C, 0, 1, 2, 3, 4, 0x8B, 255};
  EXPECT_EQ(runFuzzInput("example", input.data(), input.size(), &trace), "");
  EXPECT_NE(trace.find("  = rx 601 [8] 40 00 10 00 00 00 00 00\n  tx 581 [8] 43 00 10 00"),
            std::string::npos)
      << trace;
  EXPECT_NE(trace.find("  = rx 601 [8] 23 00 10 00 01 02 03 04\n  tx 581 [8] 80 00 10 00"),
            std::string::npos)
      << trace;  // 0x1000 is read-only
}

TEST(FuzzSession, FramesQueuedBeforeAResetCommunicationAreDiscarded) {
  // The controller refuses frames; the SDO response of node 1 and the LSS response wait in the
  // queue while LSS gives the node node-id 5 and a reset communication applies it. The reset
  // discards them (they belong to the state the node left); the boot-up of node 5 goes out.
  const std::vector<uint8_t> input = {
      0x00, 0x80,                                                        // controller refuses
      0xC0, 0x2B, 0x17, 0x10, 0x00, 0x0A, 0x00, 0x00, 0x00,              // 0x1017 = 10 ms
      0x08, 0xE5, 0x07, 0x04, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,  // LSS configuration
      0x08, 0xE5, 0x07, 0x11, 0x05, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,  // node-id 5
      0x08, 0xE5, 0x07, 0x04, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,  // LSS waiting
      0x02, 0x00, 0x00, 0x82, 0x00,                                      // NMT reset communication
      0x81, 0x5E,                                                        // takes frames; 26 ms
  };
  std::string trace;
  EXPECT_EQ(runFuzzInput("example", input.data(), input.size(), &trace), "") << trace;
  EXPECT_EQ(trace.find("  tx 581 [8] 60 17 10 00"), std::string::npos) << trace;
  EXPECT_EQ(trace.find("  tx 7E4 [8] 11 00"), std::string::npos) << trace;
  EXPECT_NE(trace.find("controller takes frames\n  tx 705 [1] 00\n"), std::string::npos) << trace;
}

TEST(FuzzSession, AnEmcyOnTheNmtIdIsRefusedNotSent) {
  // 0x1014 = not valid, then valid on 0x000, then a SYNC of the wrong length raises an EMCY.
  const std::vector<uint8_t> input = {
      0x00, 0xC0, 0x23, 0x14, 0x10, 0x00, 0x81, 0x00, 0x00, 0x80, 0xC0, 0x23,
      0x14, 0x10, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01, 0x80, 0x00, 0x05,
  };
  EXPECT_EQ(runFuzzInput("example", input.data(), input.size()), "");
}

}  // namespace
}  // namespace costa::fuzz
