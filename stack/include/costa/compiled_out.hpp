// What the node holds in place of a service compiled out of the build (costa/features.hpp).
//
// Each stand-in has the interface the node uses and does nothing: the node's code compiles
// unchanged, the calls vanish when inlined, and the service's own sources are not in the
// library at all. Stand-ins of services with objects hide those objects: every access answers
// 0x06020000 (object does not exist), as a device without the service does (CiA 301).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/emcy_consumer.hpp"
#include "costa/features.hpp"
#include "costa/heartbeat_consumer.hpp"
#include "costa/lss_slave.hpp"
#include "costa/node_guarding.hpp"
#include "costa/object_hook.hpp"
#include "costa/safety_service.hpp"
#include "costa/time_service.hpp"

namespace costa {

namespace detail {
template <bool kCompiledIn, typename Service, typename StandIn>
struct ServiceChoice {
  using Type = Service;
};
template <typename Service, typename StandIn>
struct ServiceChoice<false, Service, StandIn> {
  using Type = StandIn;
};
}  // namespace detail

/// `Service` when `kCompiledIn`, else `StandIn`.
template <bool kCompiledIn, typename Service, typename StandIn>
using ServiceIf = typename detail::ServiceChoice<kCompiledIn, Service, StandIn>::Type;

/// A member that is not there: takes the service's constructor arguments and ignores them.
class CompiledOut {
 public:
  template <typename... Ignored>
  constexpr explicit CompiledOut(Ignored&... ignored) noexcept {
    (static_cast<void>(ignored), ...);
  }
};

/// The objects of a compiled-out service: they do not exist. Stateless: one instance serves
/// every stand-in (serviceHook()), so that the stand-ins need no table of virtual functions each.
class AbsentObjects final : public ObjectHook {
 public:
  AbortCode prepareRead(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                        const ReadRequest& request) noexcept override {
    (void)dictionary;
    (void)ref;
    (void)request;
    return AbortCode::kNoObject;
  }
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override {
    (void)dictionary;
    (void)ref;
    (void)data;
    (void)length;
    return AbortCode::kNoObject;
  }
};

/// Base of the stand-ins of compiled-out services whose objects do not exist.
class AbsentService {};

/// The hook behind a service's objects: the service itself.
inline ObjectHook* serviceHook(ObjectHook& service) noexcept {
  return &service;
}
/// The hook behind a compiled-out service's objects: the shared AbsentObjects (constant
/// initialised: no constructor runs, no guard).
inline ObjectHook* serviceHook(AbsentService& standIn) noexcept {
  (void)standIn;
  static AbsentObjects absent;
  return &absent;
}

/// Node guarding compiled out: no reply to remote requests, no life time; no 0x100C/0x100D.
class AbsentNodeGuarding final : public AbsentService {
 public:
  AbsentNodeGuarding(od::ObjectDictionary& dictionary, TransmitPath& tx,
                     NodeClock& clock) noexcept {
    (void)dictionary;
    (void)tx;
    (void)clock;
  }
  void reset(uint8_t nodeId, uint8_t toggleStart) noexcept {
    (void)nodeId;
    (void)toggleStart;
  }
  void ignoreRequest() noexcept {}
  NodeGuarding::Event onRequest(NmtState state, Microseconds now) noexcept {
    (void)state;
    (void)now;
    return NodeGuarding::Event::kNone;
  }
  NodeGuarding::Event process(Microseconds now) noexcept {
    (void)now;
    return NodeGuarding::Event::kNone;
  }
  Microseconds nextDeadline() const noexcept { return kNever; }
  bool expired() const noexcept { return false; }
};

/// Heartbeat consumer compiled out: other nodes' heartbeats are not monitored; no 0x1016.
class AbsentHeartbeatConsumer final : public AbsentService {
 public:
  AbsentHeartbeatConsumer(od::ObjectDictionary& dictionary, NodeClock& clock,
                          HeartbeatMonitor* monitors, size_t capacity) noexcept {
    (void)dictionary;
    (void)clock;
    (void)monitors;
    (void)capacity;
  }
  void configure(bool reset) noexcept { (void)reset; }
  HeartbeatConsumer::Event onHeartbeat(uint8_t nodeId, uint8_t state, Microseconds now) noexcept {
    (void)nodeId;
    (void)state;
    (void)now;
    return HeartbeatConsumer::Event{};
  }
  HeartbeatConsumer::Event process(Microseconds now) noexcept {
    (void)now;
    return HeartbeatConsumer::Event{};
  }
  Microseconds nextDeadline() const noexcept { return kNever; }
  const HeartbeatMonitor* monitor(uint8_t subIndex) const noexcept {
    (void)subIndex;
    return nullptr;
  }
};

/// LSS compiled out: nothing on 0x7E5 is answered; the node-id and bit timing are the node's.
class AbsentLssSlave {
 public:
  /// `host`: the node's LssBridgeChoice (itself compiled out), or any LssSlaveHost.
  template <typename Host>
  AbsentLssSlave(TransmitPath& tx, Host& host) noexcept {
    (void)tx;
    (void)host;
  }
  void reset(const LssIdentity& identity, uint8_t activeNodeId, uint8_t pendingNodeId,
             LssBitTiming bitTiming) noexcept {
    (void)identity;
    (void)activeNodeId;
    (void)pendingNodeId;
    (void)bitTiming;
  }
  bool onFrame(const CanFrame& frame, Microseconds now) noexcept {
    (void)frame;
    (void)now;
    return false;
  }
  void process(Microseconds now) noexcept { (void)now; }
  Microseconds nextDeadline() const noexcept { return kNever; }
  bool transmissionSuspended() const noexcept { return false; }
  bool configurationState() const noexcept { return false; }
  uint8_t activeNodeId() const noexcept { return cob::kLssUnconfigured; }
  uint8_t pendingNodeId() const noexcept { return cob::kLssUnconfigured; }
  bool valid() const noexcept { return true; }
};

/// TIME compiled out: TIME frames are not routed, 0x1012 does not exist, no clock of day.
class AbsentTimeService final : public AbsentService {
 public:
  AbsentTimeService(od::ObjectDictionary& dictionary, TransmitPath& tx, NodeClock& clock,
                    FrameRouter& routes) noexcept {
    (void)dictionary;
    (void)tx;
    (void)clock;
    (void)routes;
  }
  void configure() noexcept {}
  bool consumer() const noexcept { return false; }
  uint32_t canId() const noexcept { return 0; }
  bool onFrame(const CanFrame& frame, Microseconds now) noexcept {
    (void)frame;
    (void)now;
    return false;
  }
  bool timeOfDay(Microseconds now, TimeOfDay* out) const noexcept {
    (void)now;
    (void)out;
    return false;
  }
  bool setTimeOfDay(const TimeOfDay& time, Microseconds now) noexcept {
    (void)time;
    (void)now;
    return false;
  }
  void setProducerPeriod(Microseconds period, Microseconds now) noexcept {
    (void)period;
    (void)now;
  }
  void process(Microseconds now, bool allowed) noexcept {
    (void)now;
    (void)allowed;
  }
  Microseconds nextDeadline() const noexcept { return kNever; }
  uint32_t framesIgnored() const noexcept { return 0; }
};

/// Additional SDO servers compiled out: no servers, no routes, 0x1201..0x127F do not exist.
class AbsentSdoServers final : public AbsentService {
 public:
  template <typename... Ignored>
  explicit AbsentSdoServers(Ignored&... ignored) noexcept {
    (static_cast<void>(ignored), ...);
  }
  void addRoutes(const od::ObjectDictionary& dictionary, FrameRouter& router) noexcept {
    (void)dictionary;
    (void)router;
  }
  bool onRequest(const CanFrame& frame, uint8_t server, Microseconds now) noexcept {
    (void)frame;
    (void)server;
    (void)now;
    return false;
  }
  void process(Microseconds now) noexcept { (void)now; }
  Microseconds nextDeadline() const noexcept { return kNever; }
  void reset() noexcept {}
  bool valid() const noexcept { return true; }
  size_t count() const noexcept { return 0; }
};

/// EMCY consumer compiled out: no routes, 0x1028 does not exist.
class AbsentEmcyConsumer final : public AbsentService {
 public:
  AbsentEmcyConsumer(const NodeListeners& listeners, FrameRouter& routes) noexcept {
    (void)listeners;
    (void)routes;
  }
  static void addRoutes(const od::ObjectDictionary& dictionary, FrameRouter& router) noexcept {
    (void)dictionary;
    (void)router;
  }
  bool onFrame(const CanFrame& frame, uint8_t entry) noexcept {
    (void)frame;
    (void)entry;
    return false;
  }
  uint32_t framesIgnored() const noexcept { return 0; }
};

/// Safety compiled out: no GFC, no SRDO, 0x1300..0x13FF do not exist; nothing supervises the
/// working state, which is always allowed.
class AbsentSafetyService final : public AbsentService {
 public:
  explicit AbsentSafetyService(const SafetyService::Services& services) noexcept { (void)services; }
  void addRoutes(FrameRouter& router) const noexcept { (void)router; }
  bool onGfc(const CanFrame& frame) noexcept {
    (void)frame;
    return false;
  }
  bool sendGfc(bool allowed) noexcept {
    (void)allowed;
    return false;
  }
  bool onSrdo(const CanFrame& frame, uint8_t channel, Microseconds now) noexcept {
    (void)frame;
    (void)channel;
    (void)now;
    return false;
  }
  void process(Microseconds now) noexcept { (void)now; }
  Microseconds nextDeadline() const noexcept { return kNever; }
  bool workingStateAllowed() const noexcept { return true; }
};

/// The node's safety service (GFC, SRDOs): the service, or its stand-in.
using SafetyServiceChoice = ServiceIf<features::kSafety, SafetyService, AbsentSafetyService>;

/// The node's EMCY consumer: the service, or its stand-in.
using EmcyConsumerChoice = ServiceIf<features::kEmcyConsumer, EmcyConsumer, AbsentEmcyConsumer>;

/// The node's TIME service: the service, or its stand-in.
using TimeServiceChoice = ServiceIf<features::kTime, TimeService, AbsentTimeService>;

}  // namespace costa
