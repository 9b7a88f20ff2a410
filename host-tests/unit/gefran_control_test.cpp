// The GRA/GRN simulation commands (targets/gefran/gefran_control.hpp): what each command does,
// every way a command is refused and its message, and the number parsers against the C++
// library's stream extraction, whose behaviour costa-slave had before.
#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <string>

#include "decimal_number.hpp"
#include "gefran_control.hpp"
#include "in_process_bus.hpp"

namespace costa::test {
namespace {

using gefran::ControlCommand;
using gefran::ControlError;
using gefran::ParsedControl;

std::string message(const ParsedControl& parsed) {
  std::string text(gefran::describeControlError(parsed, nullptr, 0) + 1U, '\0');
  text.resize(gefran::describeControlError(parsed, text.data(), text.size()));
  return text;
}

/// The message for a refused command, "" for an accepted one.
std::string refusal(const char* command) {
  return message(gefran::parseControl(command));
}

TEST(GefranControl, RawSetsBothChips) {
  const ParsedControl parsed = gefran::parseControl("raw 2 16383");
  ASSERT_EQ(parsed.error, ControlError::kNone);
  EXPECT_EQ(parsed.command.kind, ControlCommand::Kind::kSetRaw);
  EXPECT_EQ(parsed.command.chip1, 2U);
  EXPECT_EQ(parsed.command.chip2, 16383U);
  gefran::SimulatedHallSensors sensors;
  gefran::applyControl(parsed.command, sensors);
  EXPECT_EQ(sensors.raw(1), 2U);
  EXPECT_EQ(sensors.raw(2), 16383U);
}

TEST(GefranControl, NumbersAreReadAsAStreamReadsThem) {
  // Signs, leading zeros, white space of every kind, text after the last argument.
  const ParsedControl parsed = gefran::parseControl("\t raw\v+00012\r\n-0 and more");
  ASSERT_EQ(parsed.error, ControlError::kNone);
  EXPECT_EQ(parsed.command.chip1, 12U);
  EXPECT_EQ(parsed.command.chip2, 0U);
  const ParsedControl adjacent = gefran::parseControl("raw 5+6");  // 5, then +6
  ASSERT_EQ(adjacent.error, ControlError::kNone);
  EXPECT_EQ(adjacent.command.chip2, 6U);
}

TEST(GefranControl, AngleTurnsBothChips) {
  const ParsedControl parsed = gefran::parseControl("angle 270");
  ASSERT_EQ(parsed.error, ControlError::kNone);
  EXPECT_EQ(parsed.command.chip1, 12288U);
  EXPECT_EQ(parsed.command.chip2, 12288U);
  EXPECT_EQ(gefran::parseControl("angle -90").command.chip1, 12288U);
  EXPECT_EQ(gefran::parseControl("angle 0.0219726").command.chip1, 1U);  // 0.99996 counts
  EXPECT_EQ(gefran::parseControl("angle 2.7e2").command.chip1, 12288U);
  EXPECT_EQ(gefran::parseControl("angle .5e3").command.chip1, 6372U);  // 140 deg
  EXPECT_EQ(gefran::parseControl("angle 720x").command.chip1, 0U);
}

TEST(GefranControl, FaultRaisesAndClearsOneBit) {
  gefran::SimulatedHallSensors sensors;
  ParsedControl parsed = gefran::parseControl("fault magnet on");
  ASSERT_EQ(parsed.error, ControlError::kNone);
  EXPECT_EQ(parsed.command.kind, ControlCommand::Kind::kSetFault);
  gefran::applyControl(parsed.command, sensors);
  gefran::applyControl(gefran::parseControl("fault chip2 on").command, sensors);
  EXPECT_EQ(sensors.faults(), gefran::kMagneticField | gefran::kChip2Error);
  gefran::applyControl(gefran::parseControl("fault magnet off").command, sensors);
  EXPECT_EQ(sensors.faults(), gefran::kChip2Error);
  parsed = gefran::parseControl("fault chip1 on");
  EXPECT_EQ(parsed.command.faultBits, gefran::kChip1Error);
  EXPECT_TRUE(parsed.command.faultOn);
}

TEST(GefranControl, RefusesRawWithoutTwoReadingsInRange) {
  for (const char* command :
       {"raw", "raw 1", "raw 16384 0", "raw 0 16384", "raw -1 0", "raw 1.5 2", "raw 0x10 5",
        "raw 99999999999999999999 1", "raw a b", "raw - 1", "raw 1 +"}) {
    EXPECT_EQ(refusal(command), "usage: raw A B (0..16383)") << command;
  }
}

TEST(GefranControl, RefusesAngleWithoutANumber) {
  for (const char* command : {"angle", "angle abc", "angle .", "angle +", "angle -.e1", "angle 1e",
                              "angle 1e+", "angle inf", "angle nan", "angle 1e400", "angle -1e400",
                              "angle 1e18", "angle -2e18", "angle e5"}) {
    EXPECT_EQ(refusal(command), "usage: angle DEGREES") << command;
  }
  EXPECT_EQ(refusal("angle 1e-400"), "");  // underflow is 0, as for the stream
}

TEST(GefranControl, RefusesFaultWithoutAKnownChipAndState) {
  for (const char* command :
       {"fault", "fault chip1", "fault chip3 on", "fault chip1 maybe", "fault chip1on",
        "fault CHIP1 on", "fault chip1 ON", "fault on chip1"}) {
    EXPECT_EQ(refusal(command), "usage: fault chip1|chip2|magnet on|off") << command;
  }
}

TEST(GefranControl, NamesAnUnknownCommand) {
  EXPECT_EQ(refusal("turn 90"), "unknown command 'turn' (raw, angle, fault)");
  EXPECT_EQ(refusal("  Raw 1 2"), "unknown command 'Raw' (raw, angle, fault)");
  EXPECT_EQ(refusal("rawx 1 2"), "unknown command 'rawx' (raw, angle, fault)");
  EXPECT_EQ(refusal(""), "unknown command '' (raw, angle, fault)");
  EXPECT_EQ(refusal(" \t "), "unknown command '' (raw, angle, fault)");
}

TEST(GefranControl, MessagesAreCutLikeSnprintf) {
  const ParsedControl parsed = gefran::parseControl("turn 90");
  char small[10] = "?????????";
  EXPECT_EQ(gefran::describeControlError(parsed, small, 6), 42U);
  EXPECT_STREQ(small, "unkno");
  EXPECT_EQ(small[6], '?');
  char one[1] = {'?'};
  EXPECT_EQ(gefran::describeControlError(parsed, one, 1), 42U);
  EXPECT_EQ(one[0], '\0');
  EXPECT_EQ(gefran::describeControlError(gefran::parseControl("raw 1 2"), one, 1), 0U);
}

TEST(DecimalNumber, ParsesAsStrtodDoes) {
  for (const char* text : {"0",
                           "270",
                           "270.5",
                           "359.99",
                           "0.1",
                           "-90",
                           "+45",
                           ".5",
                           "5.",
                           "1e5",
                           "2.5E-3",
                           "-0.0219726",
                           "123456789012345",
                           "0.000000000000001",
                           "36000",
                           "1e22",
                           "9007199254740993",
                           "1e-22",
                           "00012.5000",
                           "1.2.3",
                           "1e5e3",
                           "1e5.3",
                           "0x10",
                           "1e5x"}) {
    double value = -1;
    const char* end = gefran::parseDecimal(text, &value);
    ASSERT_NE(end, nullptr) << text;
    char* expectedEnd = nullptr;
    const double expected = std::strtod(text, &expectedEnd);
    if (std::string(text) != "0x10") {  // strtod reads hexadecimal, the stream does not
      EXPECT_EQ(value, expected) << text;
      EXPECT_EQ(end, expectedEnd) << text;
    }
    std::istringstream stream(text);
    double streamed = -1;
    ASSERT_TRUE(stream >> streamed) << text;
    EXPECT_EQ(value, streamed) << text;
  }
}

TEST(DecimalNumber, IntegersAreReadAsTheStreamReadsLongs) {
  for (const char* text : {"0", "12", "+5", "-0", "-16384", "1.5", "5+6", "0x10",
                           "9223372036854775807", "-9223372036854775808"}) {
    long value = 1;
    ASSERT_NE(gefran::parseInteger(text, &value), nullptr) << text;
    std::istringstream stream(text);
    long streamed = 2;
    ASSERT_TRUE(stream >> streamed) << text;
    EXPECT_EQ(value, streamed) << text;
  }
  for (const char* text : {"", "-", "+", "x1", " 1", "9223372036854775808", "-9223372036854775809",
                           "99999999999999999999"}) {
    long value = 1;
    EXPECT_EQ(gefran::parseInteger(text, &value), nullptr) << text;
    EXPECT_EQ(value, 1) << text;
  }
}

TEST(GefranControl, CostaSlaveAnswersWithTheSameMessages) {
  InProcessBus bus("gra", 3);
  EXPECT_EQ(bus.simulate("angle 270"), "");
  EXPECT_EQ(bus.target().node().dictionary().readUnsigned(0x2000, 1, 0), 12288U);  // chip 1 raw
  EXPECT_EQ(bus.simulate("angle x"), "usage: angle DEGREES");
  EXPECT_EQ(bus.simulate("spin"), "unknown command 'spin' (raw, angle, fault)");
  InProcessBus example("example", 1);
  EXPECT_EQ(example.simulate("angle 270"), "this device has no simulation commands");
}

}  // namespace
}  // namespace costa::test
