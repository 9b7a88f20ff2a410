// costa-slave's command line, a public interface.
#include <gtest/gtest.h>

#include "slave_options.hpp"
#include "slave_runner.hpp"

namespace costa::host {
namespace {

bool parse(const std::vector<std::string>& arguments, SlaveOptions* options, std::string* error) {
  *options = SlaveOptions{};
  return parseSlaveOptions(arguments, options, error);
}

TEST(SlaveOptions, DefaultsAndEveryDocumentedOption) {
  SlaveOptions options;
  std::string error;
  ASSERT_TRUE(parse({"example"}, &options, &error)) << error;
  EXPECT_EQ(options.interfaceName, "vcan0");
  EXPECT_EQ(options.nodeId, -1);
  EXPECT_FALSE(options.trace);
  ASSERT_TRUE(
      parse({"--iface", "can1", "--node-id", "0x20", "--storage", "/tmp/x", "--trace", "example"},
            &options, &error))
      << error;
  EXPECT_EQ(options.interfaceName, "can1");
  EXPECT_EQ(options.nodeId, 32);
  EXPECT_EQ(options.storagePath, "/tmp/x");
  EXPECT_TRUE(options.trace);
  ASSERT_EQ(options.nodes.size(), 1U);
  EXPECT_EQ(options.nodes[0].device, "example");
  EXPECT_EQ(options.nodes[0].nodeId, 32);
  EXPECT_EQ(nodeStoragePath(options, 0), "/tmp/x");  // one node: the file itself
  ASSERT_TRUE(parse({"example", "--node-id", "127"}, &options, &error));
  EXPECT_EQ(options.nodeId, 127);
  ASSERT_TRUE(parse({"example", "--node-id", "0xFF"}, &options, &error));  // LSS only
  EXPECT_EQ(options.nodeId, 255);
}

TEST(SlaveOptions, HelpNeedsNoDevice) {
  SlaveOptions options;
  std::string error;
  ASSERT_TRUE(parse({"--help"}, &options, &error));
  EXPECT_TRUE(options.help);
  EXPECT_NE(slaveUsage().find("costa-slave [--iface NAME] [--node-id N] [--storage FILE] "
                              "[--trace] DEVICE"),
            std::string::npos);
}

TEST(SlaveOptions, RejectsBadInputWithOneClearLine) {
  SlaveOptions options;
  std::string error;
  EXPECT_FALSE(parse({"--node-id", "0", "example"}, &options, &error));
  EXPECT_EQ(error, "invalid node-id '0': expected 1..127 (or 255: unconfigured, LSS only)");
  EXPECT_FALSE(parse({"--node-id", "128", "example"}, &options, &error));
  EXPECT_FALSE(parse({"--node-id", "254", "example"}, &options, &error));
  EXPECT_FALSE(parse({"--node-id", "1x", "example"}, &options, &error));
  EXPECT_FALSE(parse({"--node-id"}, &options, &error));
  EXPECT_EQ(error, "--node-id needs a value");
  EXPECT_FALSE(parse({"toaster"}, &options, &error));
  EXPECT_EQ(error.rfind("unknown device 'toaster'", 0), 0U);
  EXPECT_FALSE(parse({}, &options, &error));
  EXPECT_EQ(error.rfind("no DEVICE given", 0), 0U);
  EXPECT_FALSE(parse({"--verbose", "example"}, &options, &error));
  EXPECT_FALSE(parse({"example", "example"}, &options, &error));
  EXPECT_EQ(error.find('\n'), std::string::npos);
}

TEST(SlaveOptions, SdoTimeoutInMilliseconds) {
  SlaveOptions options;
  std::string error;
  ASSERT_TRUE(parse({"example"}, &options, &error));
  EXPECT_EQ(options.sdoTimeoutMs, 0U);  // each device's own
  ASSERT_TRUE(parse({"--sdo-timeout", "3000", "example"}, &options, &error)) << error;
  EXPECT_EQ(options.sdoTimeoutMs, 3000U);
  ASSERT_TRUE(parse({"--sdo-timeout", "1", "example"}, &options, &error)) << error;
  EXPECT_EQ(options.sdoTimeoutMs, 1U);
  ASSERT_TRUE(parse({"example", "--sdo-timeout", "100000"}, &options, &error)) << error;
  EXPECT_EQ(options.sdoTimeoutMs, kLongestSdoTimeoutMs);
  for (const char* bad :
       {"0", "100001", "-5", "+5", "1.5", "2s", "", "0x10", "99999999999999999999"}) {
    EXPECT_FALSE(parse({"--sdo-timeout", bad, "example"}, &options, &error)) << bad;
    EXPECT_EQ(error, std::string("invalid SDO timeout '") + bad + "': expected 1..100000 ms");
  }
  EXPECT_FALSE(parse({"example", "--sdo-timeout"}, &options, &error));
  EXPECT_EQ(error, "--sdo-timeout needs a value");
  EXPECT_NE(slaveUsage().find("--sdo-timeout MS"), std::string::npos);
}

class NoBitRate final : public CanBitRateControl {};

// What each node is created with: the command line's node-id, storage, SDO timeout, and a
// serial number of its own when there are several.
TEST(SlaveOptions, EachNodeIsCreatedWithWhatTheCommandLineGives) {
  SlaveOptions options;
  std::string error;
  NoBitRate bitRate;
  ASSERT_TRUE(parse({"--sdo-timeout", "2500", "--storage", "/tmp/d", "example@3", "gra@0x10"},
                    &options, &error))
      << error;
  const TargetOptions second = nodeTargetOptions(options, 1, bitRate);
  EXPECT_EQ(second.nodeId, 0x10);
  EXPECT_EQ(second.storagePath, "/tmp/d/gra-2.bin");
  EXPECT_EQ(second.sdoTimeout, 2500000U);
  EXPECT_EQ(second.serialNumber, 2U);
  EXPECT_EQ(second.bitRate, &bitRate);
  ASSERT_TRUE(parse({"example"}, &options, &error)) << error;
  const TargetOptions only = nodeTargetOptions(options, 0, bitRate);
  EXPECT_EQ(only.nodeId, -1);
  EXPECT_EQ(only.storagePath, "");
  EXPECT_EQ(only.sdoTimeout, 0U);  // the device's own
  EXPECT_EQ(only.serialNumber, 0U);
}

TEST(SlaveOptions, RefusesANodeIdTheDeviceDoesNotTake) {
  SlaveOptions options;
  std::string error;
  EXPECT_FALSE(parse({"santeng", "--node-id", "127"}, &options, &error));  // 1..126 (W11)
  EXPECT_EQ(error, "invalid node-id 127 for santeng: it takes 1..126");
  ASSERT_TRUE(parse({"santeng", "--node-id", "126"}, &options, &error)) << error;
  EXPECT_EQ(options.nodeId, 126);
  ASSERT_TRUE(parse({"--node-id", "127", "example"}, &options, &error)) << error;
}

TEST(SlaveOptions, SeveralNodesEachWithItsNodeId) {
  SlaveOptions options;
  std::string error;
  ASSERT_TRUE(parse({"--storage", "/tmp/d", "solo@1", "solo@2", "gra@0x10", "m-series@3",
                     "example@255", "gra@255"},
                    &options, &error))
      << error;
  ASSERT_EQ(options.nodes.size(), 6U);
  EXPECT_EQ(options.nodes[0].device, "solo");
  EXPECT_EQ(options.nodes[0].nodeId, 1);
  EXPECT_EQ(options.nodes[2].nodeId, 16);
  EXPECT_EQ(options.nodes[3].device, "m-series");
  EXPECT_EQ(options.nodes[3].nodeId, 3);
  EXPECT_EQ(options.nodes[5].nodeId, 255);
  // One file per node, named by the device's name (not its alias) and its place in the list.
  EXPECT_EQ(nodeStoragePath(options, 0), "/tmp/d/solo-1.bin");
  EXPECT_EQ(nodeStoragePath(options, 3), "/tmp/d/mseries-4.bin");
  EXPECT_EQ(nodeStoragePath(options, 5), "/tmp/d/gra-6.bin");
  // A device without @ takes --node-id, else its own node-id (the example's is 1).
  ASSERT_TRUE(parse({"--node-id", "9", "example", "solo@1"}, &options, &error)) << error;
  EXPECT_EQ(options.nodes[0].nodeId, 9);
  ASSERT_TRUE(parse({"example", "solo@2"}, &options, &error)) << error;
  EXPECT_EQ(options.nodes[0].nodeId, -1);
}

TEST(SlaveOptions, RejectsDuplicateNodeIdsTooManyNodesAndUnknownDevices) {
  SlaveOptions options;
  std::string error;
  EXPECT_FALSE(parse({"example@1", "solo@2", "gra@1"}, &options, &error));
  EXPECT_EQ(error, "node-id 1 given twice (gra): every node needs its own");
  EXPECT_FALSE(parse({"example", "solo"}, &options, &error));  // both have node-id 1
  EXPECT_EQ(error, "node-id 1 given twice (solo): every node needs its own");
  EXPECT_FALSE(parse({"example@3", "toaster@4"}, &options, &error));
  EXPECT_EQ(error.rfind("unknown device 'toaster' (one of: ", 0), 0U) << error;
  EXPECT_FALSE(parse({"example@128"}, &options, &error));
  EXPECT_EQ(error,
            "invalid node-id '128' in 'example@128': expected 1..127 (or 255: unconfigured, LSS "
            "only)");
  EXPECT_FALSE(parse({"santeng@127"}, &options, &error));
  EXPECT_EQ(error, "invalid node-id 127 for santeng: it takes 1..126");
  std::vector<std::string> many;
  for (int i = 1; i <= 127; ++i) {
    many.push_back("example@" + std::to_string(i));
  }
  ASSERT_TRUE(parse(many, &options, &error)) << error;
  many.push_back("example@255");
  EXPECT_FALSE(parse(many, &options, &error));
  EXPECT_EQ(error, "128 nodes given: at most 127 fit on one bus");
  EXPECT_TRUE(parse({"example@255", "gra@255", "grn@255"}, &options, &error)) << error;
}

}  // namespace
}  // namespace costa::host
