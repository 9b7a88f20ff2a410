// The device list (targets/devices.cmake and its C++ twin targets/devices.hpp) and the devices
// on it: the C++ list is the CMake list, every consumer in the test program knows each device,
// and each device, built as costa-slave builds it, has attached its behaviour to its node. The
// consumers outside this program: the test device_lists (host-tests/devices/).
#include <gtest/gtest.h>

#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

#include "costa/port/memory/recording_can.hpp"
#include "device_registry.hpp"
#include "devices.hpp"
#include "fuzzed_device.hpp"
#include "replay_devices.hpp"

namespace costa::test {
namespace {

/// The list as CMake read it from targets/devices.cmake (COSTA_DEVICE_LIST, set by the build).
std::vector<std::string> cmakeList() {
  std::vector<std::string> names;
  std::istringstream list(COSTA_DEVICE_LIST);
  for (std::string name; std::getline(list, name, ',');) {
    names.push_back(name);
  }
  return names;
}

std::vector<std::string> cppList() {
  std::vector<std::string> names;
  devices::forEachDevice([&names](auto device) { names.push_back(device.name); });
  return names;
}

TEST(DeviceList, TheCppListIsTheCMakeList) {
  EXPECT_EQ(cppList(), cmakeList()) << "targets/devices.hpp and targets/devices.cmake differ";
  EXPECT_EQ(devices::kCount, cmakeList().size());
}

TEST(DeviceList, CostaSlaveTheFuzzerAndTheReplayerKnowEveryDevice) {
  std::vector<std::string> slave;
  for (const host::DeviceEntry& entry : host::devices()) {
    slave.push_back(entry.name);
  }
  EXPECT_EQ(slave, cmakeList());
  EXPECT_EQ(fuzz::fuzzedDeviceNames(), cmakeList());
  port::RecordingCan can;
  for (const std::string& name : cmakeList()) {
    EXPECT_NE(replay::buildDevice(name.c_str(), 1, can), nullptr) << name;
  }
  EXPECT_EQ(replay::buildDevice("toaster", 1, can), nullptr);
  replay::destroyDevice();
}

class EveryDevice : public ::testing::TestWithParam<std::string> {
 protected:
  /// The device as `costa-slave DEVICE` builds it: its own node-id, no storage file.
  std::unique_ptr<host::DeviceTarget> build() {
    const host::DeviceEntry* entry = host::findDevice(GetParam());
    EXPECT_NE(entry, nullptr);
    std::string error;
    auto target = entry == nullptr
                      ? nullptr
                      : host::createDevice(*entry, can_, host::TargetOptions{}, &error);
    EXPECT_EQ(error, "");
    return target;
  }

  port::RecordingCan can_;
};

TEST_P(EveryDevice, AttachesEveryHookAndListenerOfItsBehaviour) {
  const std::unique_ptr<host::DeviceTarget> device = build();
  ASSERT_NE(device, nullptr);
  EXPECT_TRUE(device->attached());
  EXPECT_EQ(device->node().statistics().hooksRefused, 0U);
  EXPECT_EQ(device->node().statistics().listenersRefused, 0U);
  device->start(0);
  device->process(0);
  EXPECT_EQ(device->node().statistics().hooksRefused, 0U);
  EXPECT_EQ(device->node().statistics().listenersRefused, 0U);
}

TEST_P(EveryDevice, RefusesAnEmptySimulationCommandWithOneLine) {
  const std::unique_ptr<host::DeviceTarget> device = build();
  ASSERT_NE(device, nullptr);
  device->start(0);
  const std::string why = device->control("");
  EXPECT_NE(why, "");
  EXPECT_EQ(why.find('\n'), std::string::npos) << why;
}

CanFrame sdoFrame(uint32_t id, std::initializer_list<uint8_t> bytes) {
  CanFrame frame;
  frame.id = id;
  frame.dlc = 8;
  size_t i = 0;
  for (const uint8_t byte : bytes) {
    frame.data[i++] = byte;
  }
  return frame;
}

/// costa-slave --sdo-timeout: the device's SDO server waits that long for the client, not its own
/// 1 s. A segmented download of 0x1017 starts and its segment never comes.
TEST_P(EveryDevice, TakesTheSdoTimeoutItIsGiven) {
  host::TargetOptions options;
  options.sdoTimeout = millisecondsToMicroseconds(3000);
  std::string error;
  const std::unique_ptr<host::DeviceTarget> device =
      host::createDevice(*host::findDevice(GetParam()), can_, options, &error);
  ASSERT_NE(device, nullptr) << error;
  device->start(0);
  (void)device->process(0);
  const uint8_t nodeId = device->node().nodeId();
  const Microseconds start = 10000;
  (void)device->process(start);
  can_.clear();
  const od::EntryRef heartbeatTime = device->node().dictionary().find(0x1017, 0);
  ASSERT_TRUE(heartbeatTime.valid());
  const auto size = static_cast<uint8_t>(heartbeatTime.size());  // UNSIGNED16, or the SOLO's 32
  device->onFrame(sdoFrame(0x600U + nodeId, {0x21, 0x17, 0x10, 0x00, size, 0x00, 0x00, 0x00}),
                  start);
  (void)device->process(start);
  ASSERT_EQ(can_.count(), 1U);
  const CanFrame& answer = can_.at(0);
  EXPECT_EQ(answer.id, 0x580U + nodeId);
  EXPECT_EQ(answer.data[0], 0x60);  // initiate download answered: the transfer waits
  can_.clear();
  auto abortsSent = [this, nodeId] {
    size_t count = 0;
    for (size_t i = 0; i < can_.count(); ++i) {
      const CanFrame& frame = can_.at(i);
      count += frame.id == 0x580U + nodeId && frame.data[0] == 0x80 ? 1U : 0U;
    }
    return count;
  };
  (void)device->process(start + millisecondsToMicroseconds(1000));
  (void)device->process(start + millisecondsToMicroseconds(2999));
  EXPECT_EQ(abortsSent(), 0U) << "aborted before the timeout it was given";
  (void)device->process(start + millisecondsToMicroseconds(3000));
  ASSERT_EQ(abortsSent(), 1U);
  for (size_t i = 0; i < can_.count(); ++i) {
    const CanFrame& frame = can_.at(i);
    if (frame.id == 0x580U + nodeId) {
      // 0x05040000: SDO protocol timed out.
      EXPECT_TRUE(sameOnWire(
          frame, sdoFrame(0x580U + nodeId, {0x80, 0x17, 0x10, 0x00, 0x00, 0x00, 0x04, 0x05})));
    }
  }
}

std::string deviceName(const ::testing::TestParamInfo<std::string>& device) {
  return device.param;
}

INSTANTIATE_TEST_SUITE_P(List, EveryDevice, ::testing::ValuesIn(cmakeList()), deviceName);

}  // namespace
}  // namespace costa::test
