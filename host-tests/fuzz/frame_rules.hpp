// Which frames a node may transmit: the CAN-IDs its node-id and its own dictionary give it, and
// the form of every frame; and which CAN-IDs its dictionary may configure.
#pragma once

#include <stdint.h>

#include <bitset>
#include <string>

#include "costa/node.hpp"

namespace costa::fuzz {

/// A set of 11-bit CAN-IDs.
class CanIdSet {
 public:
  void add(uint32_t id) {
    if (id <= kLastId) {
      ids_.set(id);
    }
  }
  bool contains(uint32_t id) const { return id <= kLastId && ids_.test(id); }
  void merge(const CanIdSet& other) { ids_ |= other.ids_; }

 private:
  static constexpr uint32_t kLastId = 0x7FF;
  std::bitset<kLastId + 1U> ids_;
};

/// CiA 301 7.3.5: CAN-IDs no configurable communication object may use (0x000, 0x001-0x07F,
/// 0x101-0x180, 0x581-0x5FF, 0x601-0x67F, 0x6E0-0x6FF, 0x701-0x77F, 0x780-0x7FF).
bool restrictedCanId(uint32_t id);

/// The CAN-IDs `node` may transmit on now, in its NMT state (CiA 301 7.3.2.2):
///  * LSS responses 0x7E4 when the device has LSS, in any state;
///  * with a node-id n (1..127): boot-up/heartbeat/guarding 0x700 + n in any state;
///  * in pre-operational and operational: SDO 0x580 + n and the 11-bit COB-ID server -> client
///    of each additional server (0x1201..0x127F sub-index 2) when not restricted, valid or not
///    (an answer under way when the server was made not valid leaves on its CAN-ID); EMCY: the
///    COB-ID of 0x1014 when valid and not restricted (0x80 + n without 0x1014); SYNC: the COB-ID of
///    0x1005 when it produces SYNC (bit 30) and the id is not restricted; TIME likewise with
///    0x1012; GFC 0x001 (without data) when 0x1300 is 1 (CiA 304);
///  * in operational: each transmit SRDO's two COB-IDs (0x1301..0x1340 sub-indices 5, 6,
///    when sub-index 1 is 1 and they are in 0x101..0x180);
///  * in operational: each TPDO whose COB-ID (0x1800..0x19FF sub-index 1) is valid, 11-bit and
///    allowed for a TPDO (the profile's range, else not restricted).
CanIdSet allowedTransmitIds(const Node& node, bool lss);

/// Empty when `frame` is a frame the node may send with `allowed` ids, else what is wrong:
/// DLC above 8, a 29-bit id, RTR, data bytes beyond the DLC that are not zero, an id outside
/// `allowed`, or a DLC other than its service's: 8 for SDO responses (0x581..0x5FF) and LSS
/// (0x7E4), 1 for boot-up, heartbeat and guarding (0x701..0x77F). (Restricted ids belong to
/// these services only, so the id tells the service.)
std::string checkTransmittedFrame(const CanFrame& frame, const CanIdSet& allowed);

/// Empty when no COB-ID in the node's dictionary gives a configurable object a restricted
/// CAN-ID: SYNC 0x1005 (consumed or produced), EMCY 0x1014 when valid, TIME 0x1012 when
/// consumed or produced, each valid EMCY consumer entry of 0x1028 and each valid COB-ID of an
/// additional SDO server 0x1201..0x127F (nor a 29-bit one), each SRDO with a direction whose
/// COB-IDs are not in 0x101..0x180, odd for the normal data and even for the inverted
/// (CiA 304), each RPDO and TPDO
/// (0x1400..0x15FF, 0x1800..0x19FF sub-index 1) when valid (a device profile's own PDO range
/// replaces the rule); else the first one that does. A node without node-id (0xFF) sends
/// nothing and its $NODEID defaults mean nothing yet: always empty.
std::string checkConfiguredCanIds(const Node& node);

/// "7E4 [8] 11 00 ..." for messages; bytes beyond the DLC in parentheses when one is not zero.
std::string describeFrame(const CanFrame& frame);

}  // namespace costa::fuzz
