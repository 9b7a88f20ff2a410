// Every transcript replayed over a real SocketCAN socket against the costa-slave executable.
#include <gtest/gtest.h>
#include <signal.h>

#include "socket_bus.hpp"
#include "transcript.hpp"

namespace costa::test {
namespace {

class TranscriptOverSocketCan : public ::testing::TestWithParam<std::string> {};

TEST_P(TranscriptOverSocketCan, Replays) {
  Transcript transcript;
  std::string error;
  ASSERT_TRUE(loadTranscript(GetParam(), &transcript, &error)) << error;
  SocketBus bus(transcript.device, transcript.nodeId);
  ASSERT_EQ(bus.error(), "");
  const std::string result = playTranscript(transcript, bus, kSocketReceiveTimeoutMs);
  const int status = bus.slave().stop(SIGTERM);
  EXPECT_EQ(result, "") << "costa-slave said:\n" << bus.slave().output();
  EXPECT_EQ(status, 0) << bus.slave().output();
}

std::string testName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param.substr(std::string(COSTA_TRANSCRIPT_DIR).size() + 1U);
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) {
      c = '_';
    }
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(All, TranscriptOverSocketCan,
                         ::testing::ValuesIn(findTranscripts(COSTA_TRANSCRIPT_DIR)), testName);

}  // namespace
}  // namespace costa::test
