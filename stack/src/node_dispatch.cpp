// Node: received frames to their services through the routing table, and the processing of
// what is due.
#include "costa/cob_ids.hpp"
#include "costa/node.hpp"

namespace costa {

void Node::buildRoutes() noexcept {
  router_.clear();
  if (features::kLss && settings_.lss) {
    router_.add(cob::kLssFromMaster, Route::kLss);
  }
  const uint8_t id = nmt_.nodeId();
  if (id == cob::kLssUnconfigured) {
    return;  // LSS only until the node has a node-id
  }
  router_.add(cob::kNmt, Route::kNmt);
  const auto sdoRequests = static_cast<uint16_t>(cob::kSdoRxBase + id);
  router_.add(sdoRequests, Route::kSdo);
  sdoServers_.addRoutes(dictionary_, router_);
  router_.add(static_cast<uint16_t>(sync_.canId()), Route::kSync);
  if (time_.consumer()) {
    router_.add(static_cast<uint16_t>(time_.canId()), Route::kTime);
  }
  EmcyConsumerChoice::addRoutes(dictionary_, router_);
  safety_.addRoutes(router_);
  for (size_t i = 0; i < pdos_.rpdoCount(); ++i) {
    const RpdoChannel& rpdo = pdos_.rpdo(i);
    if (rpdo.valid()) {
      router_.add(static_cast<uint16_t>(rpdo.canId()), Route::kRpdo, static_cast<uint8_t>(i));
    }
  }
  for (size_t i = 0; i < pdos_.tpdoCount(); ++i) {
    const TpdoChannel& tpdo = pdos_.tpdo(i);
    if (tpdo.valid()) {
      router_.add(static_cast<uint16_t>(tpdo.canId()), Route::kTpdoRequest,
                  static_cast<uint8_t>(i));
    }
  }
  // The SDO server's requests skip the lookup (onFrame), unless another route shares them;
  // built for size, every frame takes the table.
  if (kExpandFastPaths) {
    router_.setFastId(sdoRequests, Route::kSdo);
  }
}

size_t Node::receiveFilters(CanIdFilter* filters, size_t capacity) noexcept {
  if (router_.stale()) {
    buildRoutes();
  }
  size_t count = 0;
  auto add = [&](CanIdFilter filter) {
    if (count < capacity) {
      filters[count] = filter;
    }
    ++count;
  };
  for (size_t i = 0; i < router_.size(); ++i) {
    const uint16_t id = router_.at(i).id;
    if (i == 0U || router_.at(i - 1U).id != id) {  // sorted: a shared CAN-ID once
      add(CanIdFilter{id, CanIdFilter::kExact});
    }
  }
  // The error control range that errorControlFrame() takes.
  // cppcheck-suppress knownConditionTrueFalse ; two independent switches that may agree
  if ((features::kHeartbeatConsumer || features::kNodeGuarding) &&
      nmt_.nodeId() != cob::kLssUnconfigured) {
    add(CanIdFilter{static_cast<uint16_t>(cob::kErrorControlBase), 0x780});
  }
  return count;
}

COSTA_HOT_INLINE bool Node::route(const RouteEntry& entry, const CanFrame& frame) noexcept {
  switch (entry.route) {
    case Route::kNmt: return nmt_.onCommand(frame);
    case Route::kLss: {
      if constexpr (features::kLss) {
        const bool used = lss_.onFrame(frame, clock_.now);
        tx_.setGate(TransmitPath::kBitTiming, lss_.transmissionSuspended());
        clock_.schedule(lss_.nextDeadline());
        return used;
      }
      return false;  // a build without LSS has no such route
    }
    case Route::kSync: {
      if (frame.rtr || !preOrOperational()) {
        return false;
      }
      SyncEvent sync;
      if (sync_.onFrame(frame, clock_.now, &sync)) {
        handleSync(sync);
      }
      return true;
    }
    case Route::kTime: return preOrOperational() && time_.onFrame(frame, clock_.now);
    case Route::kGfc: return nmt_.state() != NmtState::kInitialising && safety_.onGfc(frame);
    case Route::kSrdo: return safety_.onSrdo(frame, entry.channel, clock_.now);
    case Route::kEmcy: return preOrOperational() && emcyConsumer_.onFrame(frame, entry.channel);
    case Route::kSdo: {
      return preOrOperational() && sdo_.onRequest(frame, clock_.now);
    }
    case Route::kSdoServer:
      return preOrOperational() && sdoServers_.onRequest(frame, entry.channel, clock_.now);
    case Route::kRpdo:
      return !frame.rtr && nmt_.state() == NmtState::kOperational &&
             pdos_.receive(entry.channel, frame, clock_.now);
    case Route::kTpdoRequest:
      return frame.rtr && nmt_.state() == NmtState::kOperational &&
             pdos_.remoteRequest(entry.channel, clock_.now);
  }
  return false;
}

void Node::onFrame(const CanFrame& frame, Microseconds now) noexcept {
  // An 8-byte request to the SDO server goes there at once: a transfer is a burst of them
  // (every segment one). A table that is stale, or routes their CAN-ID elsewhere too, has no
  // fast CAN-ID; shorter requests, which the server may refuse, take the table (and, built for
  // size, every frame). Both ways are calls of their own, so that these tests are all a frame
  // pays before. (Without a fast CAN-ID, fastId() is beyond 11 bits: the bound keeps a
  // malformed frame with that identifier off the short cut.)
  if (kExpandFastPaths && frame.id == router_.fastId() && frame.id <= FrameRouter::kLargestId &&
      frame.dlc == 8U && !frame.rtr && !frame.extended) {
    onSdoRequest(frame, now);
  } else {
    routeFrame(frame, now);
  }
}

void Node::onSdoRequest(const CanFrame& frame, Microseconds now) noexcept {
  clock_.advance(now);
  if (preOrOperational()) {
    sdo_.serve(frame.data, clock_.now);
  } else {
    ++framesIgnored_;
  }
}

void Node::routeFrame(const CanFrame& frame, Microseconds now) noexcept {
  clock_.advance(now);
  if (frame.dlc > 8U || frame.extended || frame.id > FrameRouter::kLargestId) {
    ++framesIgnored_;
    return;
  }
  if (router_.stale()) {
    buildRoutes();
  }
  const RouteEntry* entry = router_.find(frame.id);
  if (entry == nullptr) {
    if (!errorControlFrame(frame)) {
      ++framesIgnored_;
    }
    return;
  }
  bool used = false;
  if (kExpandFastPaths) {
    // The route expanded here where speed counts; the routes that share its CAN-ID after it.
    used = route(*entry, frame);
    if (router_.shared()) {
      used = routeFurther(entry, frame) || used;
    }
  } else {
    // Built for size, one loop over the frame's routes, each through the one out-of-line copy
    // (a reset may rebuild the table under our feet: then the frame has been handled; shared()
    // first, so that the usual table of one route per CAN-ID makes no call).
    do {
      used = route(*entry, frame) || used;
    } while (router_.shared() && !router_.stale() &&
             (entry = router_.nextOfSameId(entry)) != nullptr);
  }
  if (!used) {
    ++framesIgnored_;
  }
}

bool Node::routeFurther(const RouteEntry* entry, const CanFrame& frame) noexcept {
  bool used = false;
  // (a reset may rebuild the table under our feet: then the frame has been handled)
  while (!router_.stale() && (entry = router_.nextOfSameId(entry)) != nullptr) {
    used = routeOne(*entry, frame) || used;
  }
  return used;
}

bool Node::routeOne(const RouteEntry& entry, const CanFrame& frame) noexcept {
  return route(entry, frame);
}

bool Node::errorControlFrame(const CanFrame& frame) noexcept {
  // 0x701..0x77F: heartbeats of other nodes and node guarding requests (CiA 301 restricts
  // these CAN-IDs, so no route uses them).
  // cppcheck-suppress knownConditionTrueFalse ; two independent switches that may agree
  if constexpr (!features::kHeartbeatConsumer && !features::kNodeGuarding) {
    (void)frame;
    return false;  // nothing here takes them
  }
  const uint8_t id = nmt_.nodeId();
  return frame.id - (cob::kErrorControlBase + 1U) < 127U && id != cob::kLssUnconfigured &&
         nmt_.state() != NmtState::kInitialising && errorControl_.onFrame(frame, id);
}

void Node::handleSync(const SyncEvent& sync) noexcept {
  if (nmt_.state() == NmtState::kOperational) {
    pdos_.onSync(sync.counter, sync.time, sync.windowEnd);
  }
  listeners_.notify([&sync](NodeEvents& listener) { listener.onSync(sync.counter); });
}

Microseconds Node::runDue() noexcept {
  const Microseconds at = clock_.now;
  // The automatic start first: what entering operational starts (TPDOs) runs in this cycle.
  nmt_.process();
  if (features::kSdoServers && router_.stale()) {
    buildRoutes();  // an additional server's new COB-IDs end its transfer before it times out
  }
  sdo_.process(at);
  sdoServers_.process(at);
  if constexpr (features::kLss) {
    lss_.process(at);
    tx_.setGate(TransmitPath::kBitTiming, lss_.transmissionSuspended());
  }
  const NmtState state = nmt_.state();
  if (state != NmtState::kInitialising) {
    heartbeat_.process(at, heartbeatState());
    // cppcheck-suppress knownConditionTrueFalse ; two independent switches that may agree
    if constexpr (features::kHeartbeatConsumer || features::kNodeGuarding) {
      errorControl_.process(at);  // (without them, error control has no timers)
    }
    SyncEvent sync;
    if (sync_.process(at, preOrOperational(), &sync)) {
      handleSync(sync);
    }
    time_.process(at, preOrOperational());
    safety_.process(at);
    pdos_.process(at);
    emcy_.process(at, nmt_.state(), tx_);
  }
  tx_.flush(at);
  Microseconds next = earliest(sdo_.nextDeadline(), heartbeat_.nextDeadline());
  next = earliest(next, sdoServers_.nextDeadline());
  // cppcheck-suppress knownConditionTrueFalse ; two independent switches that may agree
  if constexpr (features::kHeartbeatConsumer || features::kNodeGuarding) {
    next = earliest(next, errorControl_.nextDeadline());
  }
  next = earliest(next, sync_.nextDeadline());
  next = earliest(next, time_.nextDeadline());
  next = earliest(next, safety_.nextDeadline());
  next = earliest(next, pdos_.nextDeadline());
  next = earliest(next, emcy_.nextDeadline(nmt_.state()));
  next = earliest(next, lss_.nextDeadline());
  next = earliest(next, nmt_.nextDeadline());
  // Every deadline is one of these: what the services scheduled while they ran is in them. One
  // that has passed already (work a service found due after its turn) means: at once.
  clock_.next = next != kNever && before(next, at) ? atOnce(at) : next;
  return clock_.next;
}

}  // namespace costa
