// Safety (EN 50325-5 / CiA 304): the global fail-safe command and the SRDOs. The service owns
// 0x1300..0x13FF (ServiceObjects).
//
// GFC: COB-ID 0x001, no data. 0x1300 (UNSIGNED8) enables it: 1 = valid, 0 = not valid (other
// values are refused, 0x06090030). While valid, the node consumes GFC in every state but
// initialising and tells its listeners (NodeEvents::onGlobalFailSafe), whose application enters
// its safe state; in operational it is also a safe state of the node's own (below). The node
// sends GFC when its application asks (Node::sendGlobalFailSafe), in pre-operational and
// operational. A GFC frame with data, or a remote frame, is ignored.
//
// SRDOs (srdo_configuration.hpp, srdo_channel.hpp): one channel for each SRDO of the
// dictionary (0x1301..0x1340, 0x1381..0x13C0), in storage the node sizes from it
// (NodeMemory::srdoChannels): a dictionary without SRDOs costs no channel. Every SRDO object,
// 0x13FE and 0x13FF refuse writes in operational (0x08000022); a write accepted to any SRDO object
// but 0x13FE sets 0x13FE to 0 (not valid). Entering operational, with 0x13FE = 0xA5 and every valid
// SRDO's configuration correct with its signature: each transmit SRDO sends its normal then its
// bit-inverted frame at once and every SCT; each receive SRDO is checked (srdo_channel.hpp) and its
// data written to the mapped entries. An inverted entry of its own (CiA 304: the application's
// inverted copy) fills the inverted frame as it is, and a received pair writes the inverted
// frame's bytes to it; a pair that maps the normal entry twice has its inverted data made by the
// stack (the NOT of the normal bytes). The configurations' signatures are checked again at every
// cycle.
//
// Safe state: any failure (SrdoFailure) in operational stops every SRDO, sends an EMCY
// (docs/manual-errata.md, "SRDO failures and the safe state") and tells the listeners
// (NodeEvents::onSafeState) once; the NMT state stays operational. The working state is
// allowed (Node::workingStateAllowed, which the application polls) only in operational, with a
// valid configuration and no failure since operational was entered.
//
// Context: the one that runs the node. Frames and deadlines O(1) but for the mapped entries.
#pragma once

#include <stdint.h>

#include "costa/frame_router.hpp"
#include "costa/node_clock.hpp"
#include "costa/object_hook.hpp"
#include "costa/port/can_frame.hpp"
#include "costa/srdo_channel.hpp"
#include "costa/srdo_failure.hpp"
#include "costa/transmit_path.hpp"

namespace costa {

class EmcyProducer;
class NodeListeners;
class NmtStateMachine;
class ObjectAccess;

class SafetyService : public ObjectHook {
 public:
  static constexpr uint16_t kGfcIndex = 0x1300;
  static constexpr uint16_t kGfcCanId = 0x001;

  struct Services {
    ObjectAccess& access;
    TransmitPath& tx;
    EmcyProducer& emcy;
    const NodeListeners& listeners;
    FrameRouter& routes;
    const NmtStateMachine& nmt;
    NodeClock& clock;
    SrdoChannel* channels;  ///< one per SRDO of the dictionary (NodeMemory::srdoChannels)
    uint8_t channelCount;
  };

  explicit SafetyService(const Services& services) noexcept : s_(services) {}

  /// GFC is valid: 0x1300 exists and is 1.
  bool gfcValid() const noexcept;

  /// The GFC route (Route::kGfc on 0x001) while GFC is valid; two routes (Route::kSrdo, channel
  /// 2 x slot + 1 for the inverted CAN-ID) per receive SRDO.
  void addRoutes(FrameRouter& router) const noexcept;

  /// A frame on 0x001 (GFC valid, the node past initialising): tells the listeners. False for a
  /// remote frame or one with data.
  [[nodiscard]] bool onGfc(const CanFrame& frame) noexcept;

  /// Sends GFC when it is valid and `allowed` (pre-operational or operational).
  bool sendGfc(bool allowed) noexcept;

  /// A frame of a receive SRDO (`channel` from its route).
  bool onSrdo(const CanFrame& frame, uint8_t channel, Microseconds now) noexcept;

  /// Starts and stops the SRDOs with operational, sends what is due, checks the deadlines.
  void process(Microseconds now) noexcept;
  Microseconds nextDeadline() const noexcept;

  /// Operational, started with a valid configuration, no failure since.
  bool workingStateAllowed() const noexcept;

  /// The write rules of 0x1300..0x13FF (above, srdo_configuration.hpp).
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;

 private:
  bool operational() const noexcept;
  void start(Microseconds now) noexcept;
  void stop() noexcept;
  void fail(SrdoFailure failure, uint8_t number) noexcept;
  void transmit(const SrdoChannel& channel) noexcept;
  void deliver(const SrdoChannel& channel) noexcept;
  bool unchanged(const SrdoChannel& channel) const noexcept;

  Services s_;
  uint8_t active_ = 0;    ///< slots up to the last SRDO started
  bool started_ = false;  ///< operational seen: the SRDOs were started (or failed to)
  bool running_ = false;  ///< started with a valid configuration
  bool safe_ = false;     ///< a failure since operational was entered
};

}  // namespace costa
