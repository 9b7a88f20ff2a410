// Every transcript under host-tests/transcripts, replayed in-process on a virtual clock. The
// same files are replayed over SocketCAN against costa-slave by the socketcan suite.
#include <gtest/gtest.h>

#include "in_process_bus.hpp"
#include "transcript.hpp"
#include "transcript_player.hpp"

namespace costa::test {
namespace {

class TranscriptInProcess : public ::testing::TestWithParam<std::string> {};

TEST_P(TranscriptInProcess, Replays) {
  Transcript transcript;
  std::string error;
  ASSERT_TRUE(loadTranscript(GetParam(), &transcript, &error)) << error;
  InProcessBus bus(transcript.device, transcript.nodeId);
  EXPECT_EQ(playTranscript(transcript, bus), "");
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

INSTANTIATE_TEST_SUITE_P(All, TranscriptInProcess,
                         ::testing::ValuesIn(findTranscripts(COSTA_TRANSCRIPT_DIR)), testName);

}  // namespace
}  // namespace costa::test
