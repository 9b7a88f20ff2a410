// costa-slave's command line, a public interface.
#include <gtest/gtest.h>

#include "slave_options.hpp"

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
  EXPECT_EQ(options.device, "example");
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

TEST(SlaveOptions, RefusesANodeIdTheDeviceDoesNotTake) {
  SlaveOptions options;
  std::string error;
  EXPECT_FALSE(parse({"santeng", "--node-id", "127"}, &options, &error));  // 1..126 (W11)
  EXPECT_EQ(error, "invalid node-id 127 for santeng: it takes 1..126");
  ASSERT_TRUE(parse({"santeng", "--node-id", "126"}, &options, &error)) << error;
  EXPECT_EQ(options.nodeId, 126);
  ASSERT_TRUE(parse({"--node-id", "127", "example"}, &options, &error)) << error;
}

}  // namespace
}  // namespace costa::host
