// Node: composition of the services, the application's calls, statistics.
#include "costa/node.hpp"

namespace costa {

template Node::Node(const od::Definition& definition, void* values, const NodeMemory& memory,
                    CanTransmitter& can, const NodeSettings& settings) noexcept;

bool Node::addListener(NodeEvents& listener) noexcept {
  return listeners_.add(listener);
}

bool Node::attachHook(uint16_t first, uint16_t last, ObjectHook& hook) noexcept {
  if (!hooks_.attach(first, last, hook)) {
    ++hooksRefused_;
    return false;
  }
  if (nmt_.state() != NmtState::kInitialising) {
    pdos_.refreshMappings();  // entries behind the hook now go through it
  }  // (before start() and during a reset, the reset's configuration of the PDOs resolves them)
  return true;
}

AbortCode Node::writeEntry(uint16_t index, uint8_t subIndex, const uint8_t* data,
                           size_t length) noexcept {
  od::EntryRef ref;
  const AbortCode found = dictionary_.find(index, subIndex, &ref);
  return found != AbortCode::kNone ? found : access_.write(ref, data, length);
}

void Node::flushTx() noexcept {
  tx_.flush(clock_.now);
  clock_.schedule(sdo_.nextDeadline());  // a block upload burst may go on now
  if constexpr (features::kSdoServers) {
    clock_.schedule(sdoServers_.nextDeadline());
  }
}

void Node::start(Microseconds now) noexcept {
  clock_.start(now);
  nmt_.powerOn();
}

void Node::onControllerEvent(CanControllerEvent event, Microseconds now) noexcept {
  clock_.advance(now);
  errorControl_.onControllerEvent(event);
  clock_.scheduleNow();
  process(clock_.now);  // the EMCY it raised leaves now
}

NodeStatistics Node::statistics() const noexcept {
  NodeStatistics s;
  s.framesIgnored = framesIgnored_;
  s.txRefused = tx_.refused();
  s.txDropped = tx_.dropped();
  s.txExpired = tx_.expired();
  s.txDiscarded = tx_.discarded();
  s.rxOverruns = errorControl_.rxOverruns();
  s.busOffs = errorControl_.busOffs();
  s.emcyLost = emcy_.lost();
  s.emcyConditionsFull = emcy_.conditionsFull();
  s.rpdosRefused = pdos_.rpdosRefused();
  s.unresolvableMappings = pdos_.unresolvableMappings();
  s.hooksRefused = hooksRefused_;
  s.listenersRefused = listeners_.refused();
  s.timeFramesIgnored = time_.framesIgnored();
  s.emcyFramesIgnored = emcyConsumer_.framesIgnored();
  return s;
}

}  // namespace costa
