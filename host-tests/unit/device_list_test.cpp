// The device list (targets/devices.cmake and its C++ twin targets/devices.hpp) and the devices
// on it: the C++ list is the CMake list, every consumer in the test program knows each device,
// and each device, built as costa-slave builds it, has attached its behaviour to its node. The
// consumers outside this program: the test device_lists (host-tests/devices/).
#include <gtest/gtest.h>

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

std::string deviceName(const ::testing::TestParamInfo<std::string>& device) {
  return device.param;
}

INSTANTIATE_TEST_SUITE_P(List, EveryDevice, ::testing::ValuesIn(cmakeList()), deviceName);

}  // namespace
}  // namespace costa::test
