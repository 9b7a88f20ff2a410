#include "state_rules.hpp"

#include "costa/cob_ids.hpp"

namespace costa::fuzz {
namespace {

bool nodeIdOrNone(uint8_t id) {
  return cob::isValidNodeId(id) || id == cob::kLssUnconfigured;
}

std::string checkNmt(const Node& node) {
  const NmtState state = node.state();
  if (state != NmtState::kInitialising && state != NmtState::kPreOperational &&
      state != NmtState::kOperational && state != NmtState::kStopped) {
    return "NMT state " + std::to_string(static_cast<int>(state));
  }
  if (!nodeIdOrNone(node.nodeId())) {
    return "NMT: node-id " + std::to_string(node.nodeId());
  }
  if ((state == NmtState::kInitialising) != (node.nodeId() == cob::kLssUnconfigured)) {
    return std::string("NMT: ") + describe(state) + " with node-id " +
           std::to_string(node.nodeId());
  }
  if (!nodeIdOrNone(node.pendingNodeId())) {
    return "NMT: node-id for the next reset communication " + std::to_string(node.pendingNodeId());
  }
  return "";
}

std::string checkLss(const Node& node, bool lss) {
  const LssSlave& slave = node.lss();
  if (!slave.valid()) {
    return "LSS slave state not valid";
  }
  if (slave.activeNodeId() != node.nodeId()) {
    return "LSS active node-id " + std::to_string(slave.activeNodeId()) +
           " but the node runs with " + std::to_string(node.nodeId());
  }
  if (!lss && (slave.state() != LssState::kWaiting || slave.transmissionSuspended())) {
    return "LSS slave active on a device without LSS";
  }
  return "";
}

std::string checkSdo(const Node& node) {
  const SdoServer& sdo = node.sdo();
  if (!sdo.valid()) {
    return "SDO server state not valid";
  }
  if (!node.sdoServers().valid()) {
    return "an additional SDO server's state is not valid";
  }
  if (sdo.busy() && node.state() != NmtState::kPreOperational &&
      node.state() != NmtState::kOperational) {
    return std::string("SDO transfer running in ") + describe(node.state());
  }
  return "";
}

/// The node raises EMCY 0x8130 for entry n of 0x1016 (source n) only while that entry has
/// timed out: a new value of the entry, or reset communication, clears it.
std::string checkHeartbeatErrors(const Node& node) {
  constexpr uint16_t kHeartbeatError = 0x8130;
  for (unsigned entry = 1; entry <= 0xFFU; ++entry) {
    const auto sub = static_cast<uint8_t>(entry);
    const HeartbeatMonitor* monitor = node.heartbeatConsumer().monitor(sub);
    if (monitor == nullptr) {
      break;
    }
    if (node.errorActive(kHeartbeatError, sub) && !monitor->timedOut) {
      return "EMCY 0x8130 of 0x1016 sub-index " + std::to_string(entry) +
             " active while its entry has not timed out";
    }
  }
  return "";
}

/// The clock of day, once set, is a time of day (TIME frames past midnight are refused).
std::string checkTime(const Node& node) {
  TimeOfDay time;
  if (node.timeOfDay(&time) && time.milliseconds >= TimeOfDay::kMillisecondsPerDay) {
    return "clock of day past midnight: " + std::to_string(time.milliseconds) + " ms";
  }
  return "";
}

}  // namespace

std::string checkStateMachines(const Node& node, bool lss) {
  std::string problem = checkNmt(node);
  if (problem.empty()) {
    problem = checkLss(node, lss);
  }
  if (problem.empty()) {
    problem = checkSdo(node);
  }
  if (problem.empty()) {
    problem = checkTime(node);
  }
  if (problem.empty()) {
    problem = checkHeartbeatErrors(node);
  }
  return problem;
}

namespace {

IndicatorState expectedRun(const Node& node) {
  if (node.lss().configurationState()) {
    return IndicatorState::kFlickering;
  }
  switch (node.state()) {
    case NmtState::kPreOperational: return IndicatorState::kBlinking;
    case NmtState::kOperational: return IndicatorState::kOn;
    case NmtState::kStopped: return IndicatorState::kSingleFlash;
    case NmtState::kInitialising: break;
  }
  return IndicatorState::kOff;
}

/// An LED in a steady state shows it.
bool showsSteadyState(IndicatorState state, bool lit) {
  return (state != IndicatorState::kOn || lit) && (state != IndicatorState::kOff || !lit);
}

}  // namespace

std::string checkIndicators(const Node& node, const Indicators& indicators, bool runLit,
                            bool errorLit) {
  if (indicators.run() != expectedRun(node)) {
    return "RUN indicator state " + std::to_string(static_cast<int>(indicators.run())) +
           " in NMT state " + describe(node.state());
  }
  if (node.busOff() != (indicators.error() == IndicatorState::kOn)) {
    return "ERROR indicator on exactly while bus-off: state " +
           std::to_string(static_cast<int>(indicators.error()));
  }
  if (!node.busOff() && node.lss().configurationState() &&
      indicators.error() != IndicatorState::kFlickering) {
    return "ERROR indicator not flickering in LSS configuration state";
  }
  if (!showsSteadyState(indicators.run(), runLit) ||
      !showsSteadyState(indicators.error(), errorLit)) {
    return "an indicator's LED does not show its steady state";
  }
  return "";
}

}  // namespace costa::fuzz
