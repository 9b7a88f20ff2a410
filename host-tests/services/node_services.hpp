// Every service of a node composed without Node, for the NmtStateMachine and ErrorControl tests.
#pragma once

#include <gtest/gtest.h>
#include <stddef.h>
#include <stdint.h>

#include <memory>
#include <string>
#include <vector>

#include "costa/bit_timing_switch.hpp"
#include "costa/emcy_producer.hpp"
#include "costa/error_control.hpp"
#include "costa/frame_router.hpp"
#include "costa/heartbeat_producer.hpp"
#include "costa/hook_registry.hpp"
#include "costa/lss_bridge.hpp"
#include "costa/nmt_state_machine.hpp"
#include "costa/node_events.hpp"
#include "costa/node_settings.hpp"
#include "costa/object_access.hpp"
#include "costa/pdo_engine.hpp"
#include "costa/sdo_server.hpp"
#include "costa/service_objects.hpp"
#include "costa/stored_parameters.hpp"
#include "costa/sync_service.hpp"
#include "costa/transmit_path.hpp"
#include "recording_listener.hpp"
#include "service_fixture.hpp"

namespace costa::test {

/// Every service of a node over one dictionary, transmit path and clock.
struct NodeServices {
  NodeServices(od::ObjectDictionary& dictionary, TransmitPath& tx, NodeClock& clock,
               const NodeSettings& nodeSettings)
      : settings(nodeSettings),
        hooks(bindings, 2),
        access(dictionary, hooks, services),
        emcy(dictionary, settings.profile.emcy, clock, conditions, 4, pending, 4),
        pdoContext{access, tx, settings.profile.pdo, emcy, listeners, clock, router},
        sdo(access, tx, settings.profile.sdo, clock, sdoBuffer, sizeof(sdoBuffer),
            settings.sdoTimeout),
        sdoServers(access, tx, settings.profile.sdo, clock, sdoServerSlots, sdoBuffer, 0U, 0U,
                   settings.sdoTimeout, router),
        heartbeat(dictionary, tx, clock),
        sync(dictionary, tx, emcy, clock, router),
        time(dictionary, tx, clock, router),
        emcyConsumer(listeners, router),
        pdos(pdoContext, rpdos, 2, tpdos, 2),
        stored(dictionary, settings, listeners),
        bitTiming(settings.bitRateControl, settings.bitTiming),
        router(routes, 8),
        errorControl(dictionary, settings.profile.errorControl, tx, clock, nmt, monitors, 2),
        lssBridge(nmt),
        lss(tx, lssBridge),
        nmt(NmtStateMachine::Services{dictionary, settings, clock, listeners, tx, sdo, sdoServers,
                                      heartbeat, emcy, sync, time, pdos, errorControl, stored,
                                      bitTiming, lss, router},
            settings.nodeId),
        services(ServiceObjects::Hooks{&emcy, &sync, &errorControl.guardingObjects(),
                                       &stored.commands(), &errorControl.consumerObjects(),
                                       &heartbeat, serviceHook(time), serviceHook(emcyConsumer),
                                       nullptr, &pdos, serviceHook(sdoServers)}) {
    access.setObserver(stored.autoSave());
    pdos.bind();
    EXPECT_TRUE(listeners.add(listener));
  }
  NodeServices(const NodeServices&) = delete;
  NodeServices& operator=(const NodeServices&) = delete;
  NodeServices(NodeServices&&) = delete;
  NodeServices& operator=(NodeServices&&) = delete;
  ~NodeServices() = default;

  NodeSettings settings;
  NodeListeners listeners;
  RecordingListener listener;
  HookBinding bindings[2];
  HookRegistry hooks;
  ObjectAccess access;
  EmcyCondition conditions[4];
  PendingEmcy pending[4];
  EmcyProducer emcy;
  PdoContext pdoContext;
  uint8_t sdoBuffer[32] = {};
  SdoServer sdo;
  SdoServerSlot* sdoServerSlots = nullptr;  ///< no additional servers
  SdoServersChoice sdoServers;
  HeartbeatProducer heartbeat;
  SyncService sync;
  TimeServiceChoice time;
  EmcyConsumerChoice emcyConsumer;
  RpdoChannel rpdos[2];
  TpdoChannel tpdos[2];
  PdoEngine pdos;
  StoredParametersChoice stored;
  BitTimingSwitch bitTiming;
  RouteEntry routes[8];
  FrameRouter router;
  HeartbeatMonitor monitors[2];
  ErrorControl errorControl;
  LssBridge lssBridge;
  NmtStateMachine::LssSlaveService lss;
  NmtStateMachine nmt;
  ServiceObjects services;  ///< after the services it names; `access` refers to it
};

/// A test of the composed services: build() them with the settings of the test, then power on.
class NodeServicesTest : public ServiceTest {
 protected:
  /// Builds the services with `settings` (node-id kNodeId unless the test says otherwise).
  NodeServices& build(const NodeSettings& settings = withNodeId(kNodeId)) {
    services_ = std::make_unique<NodeServices>(dictionary_, tx_, clock_, settings);
    return *services_;
  }
  static NodeSettings withNodeId(uint8_t nodeId) {
    NodeSettings settings;
    settings.nodeId = nodeId;
    return settings;
  }
  /// Builds with `settings` and powers on; the boot-up and the first events count as read.
  NodeServices& powerOn(const NodeSettings& settings = withNodeId(kNodeId)) {
    NodeServices& node = build(settings);
    node.nmt.powerOn();
    (void)sent();
    (void)node.listener.take();
    return node;
  }
  /// An NMT command frame: `command` for `nodeId` (0: every node).
  static CanFrame nmtCommand(NmtCommand command, uint8_t nodeId) {
    return frame(0x000, {static_cast<uint8_t>(command), nodeId});
  }
  /// Sends what the EMCY producer holds, as the node's processing does.
  std::vector<std::string> emcySent() {
    services_->emcy.process(clock_.now, services_->nmt.state(), tx_);
    return sent();
  }
  using Events = std::vector<std::string>;

  std::unique_ptr<NodeServices> services_;
};

}  // namespace costa::test
