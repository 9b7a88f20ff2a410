// A simulated Santeng channel that runs at a steady speed counts on in one sum: run() over many
// milliseconds gives exactly the readings of as many runs of one millisecond, which step.
#include <gtest/gtest.h>

#include "simulated_channel.hpp"

namespace costa::santeng {
namespace {

void expectSameReadings(const ChannelReading& a, const ChannelReading& b, int at) {
  EXPECT_EQ(a.speedRpm, b.speedRpm) << "at " << at << " ms";
  EXPECT_EQ(a.appliedPermille, b.appliedPermille) << "at " << at << " ms";
  EXPECT_EQ(a.speedPermille, b.speedPermille) << "at " << at << " ms";
  EXPECT_EQ(a.encoderCount, b.encoderCount) << "at " << at << " ms";
  EXPECT_EQ(a.hallCount, b.hallCount) << "at " << at << " ms";
  EXPECT_EQ(a.motorAmpsTimes10, b.motorAmpsTimes10) << "at " << at << " ms";
  EXPECT_EQ(a.batteryAmpsTimes10, b.batteryAmpsTimes10) << "at " << at << " ms";
  EXPECT_EQ(a.motorFlags, b.motorFlags) << "at " << at << " ms";
}

/// `phases` of (command, milliseconds), run one millisecond at a time by one channel and in one
/// run() per phase by the other; the readings agree after each phase.
struct Phase {
  ChannelCommand command;
  int milliseconds;
};

void runBoth(std::initializer_list<Phase> phases, bool stalled = false) {
  SimulatedChannel stepped;
  SimulatedChannel whole;
  stepped.setStalled(stalled);
  whole.setStalled(stalled);
  int at = 0;
  for (const Phase& phase : phases) {
    for (int ms = 0; ms < phase.milliseconds; ++ms) {
      stepped.run(phase.command, 1000);
    }
    whole.run(phase.command, static_cast<Microseconds>(phase.milliseconds) * 1000U);
    at += phase.milliseconds;
    expectSameReadings(stepped.reading(), whole.reading(), at);
  }
  EXPECT_NE(stepped.reading().encoderCount, 0);  // the scenario moved
}

ChannelCommand speed(int16_t permille, ChannelMode mode = ChannelMode::kOpenLoopSpeed) {
  ChannelCommand command;
  command.mode = mode;
  command.motorCommand = permille;
  command.acceleration = 5000;  // 500 RPM/s
  command.deceleration = 20000;
  command.maxRpm = 3000;
  command.encoderLines = 333;  // counts that do not divide evenly
  return command;
}

TEST(SantengChannel, ASteadySpeedCountsAsItsStepsWouldOverManySeconds) {
  runBoth({{speed(517), 4500}, {speed(517), 3250}});
}

TEST(SantengChannel, AReversalCountsAsItsStepsWouldThroughZero) {
  // The remainders of the forward run have the other sign than the speed backwards.
  runBoth({{speed(401), 1777}, {speed(-263), 6001}, {speed(389), 5003}});
}

TEST(SantengChannel, ASlowReversalAtOnceCountsThroughTheRemaindersOfTheForwardRun) {
  // 1 RPM, changed at once: the sums that go backwards start from the forward run's remainders.
  ChannelCommand slow = speed(1);
  slow.maxRpm = 1000;
  slow.acceleration = 0;
  slow.deceleration = 0;
  ChannelCommand back = slow;
  back.motorCommand = -1;
  runBoth({{slow, 2003}, {back, 4001}, {slow, 3000}});
}

TEST(SantengChannel, ClosedLoopAndAMaximumOfItsOwnCountTheSame) {
  ChannelCommand fast = speed(-1000, ChannelMode::kClosedLoopSpeed);
  fast.maxRpm = 65535;
  fast.encoderLines = 65535;
  fast.acceleration = 0;  // at once
  // A minute at the largest speed and encoder: sums that would overflow in one piece.
  runBoth({{fast, 61234}, {speed(700, ChannelMode::kClosedLoopSpeed), 3003}});
}

TEST(SantengChannel, AStalledMotorAndACountPositionMoveStepAsBefore) {
  runBoth({{speed(600), 1500}}, /*stalled=*/false);
  SimulatedChannel stepped;
  SimulatedChannel whole;
  for (SimulatedChannel* channel : {&stepped, &whole}) {
    channel->setStalled(true);
  }
  for (int ms = 0; ms < 2500; ++ms) {
    stepped.run(speed(600), 1000);
  }
  whole.run(speed(600), 2500000U);
  expectSameReadings(stepped.reading(), whole.reading(), 2500);
  EXPECT_NE(whole.reading().motorFlags, 0U);  // stalled: commanded but not turning

  ChannelCommand position = speed(0, ChannelMode::kCountPosition);
  position.targetCount = 123457;
  position.positionSpeed = 2500;
  runBoth({{position, 9000}, {position, 1000}});
}

}  // namespace
}  // namespace costa::santeng
