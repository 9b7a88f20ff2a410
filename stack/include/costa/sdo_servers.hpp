// Additional SDO servers (CiA 301 7.5.2.33, objects 0x1201..0x127F): each object of that range
// in the dictionary is one more SdoServer, with its own transfer state and buffer, running at
// the same time as the default server (0x1200) and the others. Sub-index 1 is the COB-ID
// client -> server (the requests), 2 the COB-ID server -> client (the responses), 3 the node-id
// of the SDO client (informative). In both COB-IDs bit 31 set means not valid, bit 30 is the
// dynamic-allocation flag (kept, not used), bit 29 (29-bit CAN-ID) is refused; a server serves
// while both are valid.
//
// Rules on writes (0x06090030 when broken): the CAN-ID bits (0..30) change only while the entry
// is not valid (its stored bit 31 set) or together with setting it; a valid entry takes no
// restricted CAN-ID (cob::isRestrictedCanId); the client's node-id is 1..127 (0x06090032 below,
// 0x06090031 above). A COB-ID written rebuilds the routing table; at the rebuild, a server whose
// COB-IDs changed ends any transfer in progress (without a frame) and takes the new ones.
//
// Storage: NodeMemory::sdoServerSlots and sdoServerBuffers, one slot and one buffer of
// sdoBufferSize bytes per server, sized by the generated Capacity::kSdoServers (none in the
// dictionary, none in RAM). Context: the one that runs the node.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/compiled_out.hpp"
#include "costa/features.hpp"
#include "costa/frame_router.hpp"
#include "costa/object_hook.hpp"
#include "costa/sdo_server.hpp"

namespace costa {

/// Room for one additional server (SdoServers constructs it in place) and the COB-IDs it was
/// configured with.
struct SdoServerSlot {
  alignas(SdoServer) unsigned char bytes[sizeof(SdoServer)];
  SdoServer* server;  ///< the server constructed in `bytes`
  uint32_t request;   ///< COB-ID client -> server as last applied
  uint32_t response;  ///< COB-ID server -> client as last applied
};

class SdoServers : public ObjectHook {
 public:
  static constexpr uint16_t kFirst = 0x1201;
  static constexpr uint16_t kLast = 0x127F;

  /// Servers in `slots[0..count)`, the k-th for the k-th object of 0x1201..0x127F in the
  /// dictionary; server k transfers through `buffers + k * bufferSize`. Not valid until the
  /// first addRoutes().
  SdoServers(ObjectAccess& access, TransmitPath& tx, const SdoProfile& profile, NodeClock& clock,
             SdoServerSlot* slots, uint8_t* buffers, size_t bufferSize, size_t count,
             Microseconds timeout, FrameRouter& routes) noexcept;
  SdoServers(const SdoServers&) = delete;
  SdoServers& operator=(const SdoServers&) = delete;
  ~SdoServers() noexcept;

  /// Applies the COB-IDs of 0x1201..0x127F (a server whose COB-IDs changed ends its transfer)
  /// and adds a route (Route::kSdoServer, channel = server) for every valid server. O(servers
  /// log objects).
  void addRoutes(const od::ObjectDictionary& dictionary, FrameRouter& router) noexcept;

  /// A request to `server` (a route's channel).
  [[nodiscard]] bool onRequest(const CanFrame& frame, uint8_t server, Microseconds now) noexcept {
    return at(server).onRequest(frame, now);
  }
  void process(Microseconds now) noexcept;
  Microseconds nextDeadline() const noexcept;
  /// Every server drops its transfer without a frame (NMT reset, stopped state).
  void reset() noexcept;
  /// Every server's SdoServer::valid().
  bool valid() const noexcept;
  size_t count() const noexcept { return count_; }

  /// 0x1201..0x127F: the rules above; an accepted COB-ID rebuilds the routing table.
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;

 private:
  SdoServer& at(size_t server) noexcept { return *slots_[server].server; }
  const SdoServer& at(size_t server) const noexcept { return *slots_[server].server; }

  SdoServerSlot* slots_;
  size_t count_;
  FrameRouter& routes_;
};

/// The node's additional SDO servers: the servers, or their stand-in.
using SdoServersChoice = ServiceIf<features::kSdoServers, SdoServers, AbsentSdoServers>;

}  // namespace costa
