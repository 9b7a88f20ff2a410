// A PdoEngine over the service dictionary with its EMCY producer, routing table and a listener.
#pragma once

#include <gtest/gtest.h>
#include <stddef.h>
#include <stdint.h>

#include "costa/emcy_producer.hpp"
#include "costa/frame_router.hpp"
#include "costa/hook_registry.hpp"
#include "costa/node_events.hpp"
#include "costa/object_access.hpp"
#include "costa/pdo_engine.hpp"
#include "costa/service_objects.hpp"
#include "recording_listener.hpp"
#include "service_fixture.hpp"

namespace costa::test {

class PdoEngineTest : public ServiceTest {
 protected:
  PdoEngineTest()
      : hooks_(bindings_, 2),
        services_(ServiceObjects::Hooks{}),
        access_(dictionary_, hooks_, services_),
        emcy_(dictionary_, emcyProfile_, clock_, conditions_, 4, pending_, 4),
        router_(routes_, 8),
        context_{access_, tx_, profile_, emcy_, listeners_, clock_, router_},
        pdos_(context_, rpdos_, 2, tpdos_, 2) {
    emcy_.setNodeId(kNodeId);
    EXPECT_TRUE(listeners_.add(listener_));
    pdos_.bind();
    pdos_.configure();
  }

  /// The EMCY frames raised so far (the producer queues them; this sends them).
  std::vector<std::string> emcySent() {
    emcy_.process(clock_.now, NmtState::kOperational, tx_);
    return sent();
  }
  /// Makes the PDO at `communicationIndex` invalid (bit 31 of its COB-ID), through the engine.
  void invalidate(uint16_t communicationIndex, uint32_t canId) {
    EXPECT_EQ(write(pdos_, communicationIndex, 1, 0x80000000U | canId, 4), AbortCode::kNone);
  }
  void validate(uint16_t communicationIndex, uint32_t canId) {
    EXPECT_EQ(write(pdos_, communicationIndex, 1, canId, 4), AbortCode::kNone);
  }

  HookBinding bindings_[2];
  HookRegistry hooks_;
  ServiceObjects services_;
  ObjectAccess access_;
  EmcyProfile emcyProfile_;
  EmcyCondition conditions_[4];
  PendingEmcy pending_[4];
  EmcyProducer emcy_;
  RouteEntry routes_[8];
  FrameRouter router_;
  PdoProfile profile_;
  NodeListeners listeners_;
  RecordingListener listener_;
  PdoContext context_;
  RpdoChannel rpdos_[2];
  TpdoChannel tpdos_[2];
  PdoEngine pdos_;
};

}  // namespace costa::test
