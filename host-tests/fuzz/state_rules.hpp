// The node's state machines are in states they can be in.
#pragma once

#include <string>

#include "costa/indicators.hpp"
#include "costa/node.hpp"

namespace costa::fuzz {

/// Empty when, after start():
///  * NMT: the state is one of the four CiA 301 states, the node-id is 1..127 or 0xFF (none),
///    the node is initialising exactly when it has no node-id, and the node-id to apply at the
///    next reset communication is 1..127 or 0xFF;
///  * LSS: LssSlave::valid(), its active node-id is the node's, and a device without LSS has
///    left it in waiting state with no bit timing switch;
///  * SDO: SdoServer::valid(), and a transfer runs only in pre-operational or operational;
///  * TIME: the clock of day, once set, is before midnight;
///  * heartbeat consumer: the EMCY 0x8130 condition of entry n of 0x1016 (source n) is active
///    only while that entry has timed out.
/// Else what is wrong.
std::string checkStateMachines(const Node& node, bool lss);

/// The CiA 303-3 indicators follow the node (indicators.hpp): RUN flickers in LSS configuration
/// state, else blinks in pre-operational, is on in operational, single-flashes when stopped and
/// is off without a node-id; ERROR is on while bus-off and flickers in LSS configuration state
/// otherwise; an LED whose state is on is lit (`runLit`, `errorLit`), one whose state is off is
/// dark. Else what is wrong.
std::string checkIndicators(const Node& node, const Indicators& indicators, bool runLit,
                            bool errorLit);

}  // namespace costa::fuzz
