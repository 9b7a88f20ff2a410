// costa-slave on vcan receives the driver's error frames: EMCY on the bus, the trace, and the
// counters at shutdown. On vcan no driver reports anything, so the test socket sends the error
// frames a driver would (the kernel delivers them to sockets that asked for error frames).
#include <gtest/gtest.h>
#include <linux/can.h>
#include <linux/can/error.h>
#include <signal.h>

#include "socket_bus.hpp"
#include "transcript_player.hpp"

namespace costa::test {
namespace {

TEST(SlaveProcessOnVcan, ErrorFramesOfTheDriverBecomeEmcyAndAreCounted) {
  SocketBus bus("example", 1, {"--trace"});
  ASSERT_EQ(bus.error(), "");
  EXPECT_EQ(playText("tx 701 [1] 00", bus, kSocketReceiveTimeoutMs), "");
  ASSERT_TRUE(bus.sendErrorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_OVERFLOW));
  EXPECT_EQ(playText("tx 081 [8] 10 81 11 00 00 00 00 00", bus, kSocketReceiveTimeoutMs), "");
  ASSERT_TRUE(bus.sendErrorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_PASSIVE));
  EXPECT_EQ(playText("tx 081 [8] 20 81 11 00 00 00 00 00", bus, kSocketReceiveTimeoutMs), "");
  ASSERT_TRUE(bus.sendErrorFrame(CAN_ERR_BUSOFF, 0));
  ASSERT_TRUE(bus.sendErrorFrame(CAN_ERR_RESTARTED, 0));
  EXPECT_EQ(playText(R"(
    tx 081 [8] 00 00 00 00 00 00 00 00   # error passive is over
    tx 081 [8] 40 81 11 00 00 00 00 00   # recovered from bus-off
  )",
                     bus, kSocketReceiveTimeoutMs),
            "");
  ASSERT_TRUE(bus.sendErrorFrame(CAN_ERR_PROT | CAN_ERR_ACK, 0));  // not asked for: unseen
  EXPECT_EQ(playText("rx 601 [8] 40 00 10 00 00 00 00 00\ntx 581 [8] 43 00 10 00 00 00 00 00", bus,
                     kSocketReceiveTimeoutMs),
            "");
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0);
  const std::string output = bus.slave().output();
  EXPECT_NE(output.find("rx error frame                      controller: rx overrun"),
            std::string::npos)
      << output;
  EXPECT_NE(output.find("controller: bus-off recovered"), std::string::npos) << output;
  EXPECT_NE(output.find("counters                         tx dropped 0, tx expired 0, EMCY "
                        "lost 0, error frames 4, rx overruns 1, bus-offs 1"),
            std::string::npos)
      << output;
  EXPECT_NE(output.find("costa-slave: stopped: tx dropped 0, tx expired 0, EMCY lost 0, error "
                        "frames 4, rx overruns 1, bus-offs 1\n"),
            std::string::npos)
      << output;
}

}  // namespace
}  // namespace costa::test
