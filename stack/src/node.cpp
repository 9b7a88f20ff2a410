// Node: composition of the services, the application's calls, statistics.
#include "costa/node.hpp"

namespace costa {

Node::Node(const od::Definition& definition, const NodeMemory& memory, CanTransmitter& can,
           const NodeSettings& settings) noexcept
    : settings_(settings),
      dictionary_(definition, memory.values),
      tx_(can, memory.txSlots, memory.txCapacity),
      hooks_(memory.hookSlots, memory.hookCapacity),
      access_(dictionary_, hooks_, services_),
      emcy_(dictionary_, settings_.profile.emcy, clock_, memory.emcyConditions,
            memory.emcyConditionCapacity, memory.emcyQueue, memory.emcyQueueCapacity),
      pdoContext_{access_, tx_, settings_.profile.pdo, emcy_, listeners_, clock_, router_},
      sdo_(access_, tx_, settings_.profile.sdo, clock_, memory.sdoBuffer, memory.sdoBufferSize,
           settings_.sdoTimeout),
      sdoServers_(access_, tx_, settings_.profile.sdo, clock_, memory.sdoServerSlots,
                  memory.sdoServerBuffers, memory.sdoBufferSize, memory.sdoServerCount,
                  settings_.sdoTimeout, router_),
      heartbeat_(dictionary_, tx_, clock_),
      sync_(dictionary_, tx_, emcy_, clock_, router_),
      time_(dictionary_, tx_, clock_, router_),
      emcyConsumer_(listeners_, router_),
      safety_(SafetyService::Services{access_, tx_, emcy_, listeners_, router_, nmt_, clock_,
                                      memory.srdoChannels, static_cast<uint8_t>(memory.srdoCount)}),
      pdos_(pdoContext_, memory.rpdos, memory.rpdoCapacity, memory.tpdos, memory.tpdoCapacity),
      stored_(dictionary_, settings_, listeners_),
      bitTiming_(settings_.bitRateControl, settings_.bitTiming),
      router_(memory.routes, memory.routeCapacity),
      errorControl_(dictionary_, settings_.profile.errorControl, tx_, emcy_, clock_, listeners_,
                    nmt_, memory.heartbeatMonitors, memory.heartbeatMonitorCapacity),
      lssBridge_(settings_, bitTiming_, stored_, listeners_, nmt_),
      lss_(tx_, lssBridge_),
      nmt_(NmtStateMachine::Services{dictionary_, settings_, clock_, listeners_, tx_, sdo_,
                                     sdoServers_, heartbeat_, emcy_, sync_, time_, pdos_,
                                     errorControl_, stored_, bitTiming_, lss_, router_},
           settings_.nodeId),
      services_(ServiceObjects::Hooks{&emcy_, &sync_, &errorControl_.guardingObjects(),
                                      &stored_.commands(), &errorControl_.consumerObjects(),
                                      &heartbeat_, serviceHook(time_), serviceHook(emcyConsumer_),
                                      serviceHook(safety_), &pdos_, serviceHook(sdoServers_)}) {
  access_.setObserver(stored_.autoSave());
  pdos_.bind();
}

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
