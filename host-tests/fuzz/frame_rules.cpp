#include "frame_rules.hpp"

#include <stdio.h>

#include "costa/cob_ids.hpp"

namespace costa::fuzz {
namespace {

constexpr uint32_t kInvalidBit = 0x80000000U;  // bit 31 (CiA 301 polarity: "not valid")
constexpr uint32_t kSyncProducerBit = 0x40000000U;
constexpr uint32_t kExtendedBit = 0x20000000U;
constexpr uint32_t kReservedBits = 0x1FFFF800U;  // bits 28..11 of an 11-bit COB-ID
constexpr uint32_t kIdBits = 0x7FFU;
constexpr uint16_t kEmcyCobId = 0x1014;
constexpr uint16_t kSyncCobId = 0x1005;
constexpr uint16_t kFirstRpdo = 0x1400;
constexpr uint16_t kLastRpdo = 0x15FF;
constexpr uint16_t kFirstTpdo = 0x1800;
constexpr uint16_t kLastTpdo = 0x19FF;

/// An 11-bit COB-ID value without bit 29 or reserved bits.
bool plainStandardId(uint32_t value) {
  return (value & (kExtendedBit | kReservedBits)) == 0U;
}

/// A PDO communication parameter's COB-ID (sub-index 1), decoded by the profile's polarity.
struct PdoCobId {
  uint16_t index;
  uint32_t value;
  bool valid;  ///< valid, 11-bit, no reserved bits set
  uint32_t id;
};

/// Calls `visit(PdoCobId, receive)` for every PDO communication parameter of the node.
template <typename Visit>
void forEachPdo(const Node& node, Visit visit) {
  const od::ObjectDictionary& dictionary = node.dictionary();
  const od::Definition& definition = dictionary.definition();
  const bool cia301 = node.profile().pdo.cobIdPolarity == PdoCobIdPolarity::kCia301;
  for (size_t i = 0; i < definition.objectCount; ++i) {
    const uint16_t index = definition.objects[i].index;
    const bool receive = index >= kFirstRpdo && index <= kLastRpdo;
    if (!receive && (index < kFirstTpdo || index > kLastTpdo)) {
      continue;
    }
    const od::EntryRef ref = dictionary.find(index, 1);
    if (!ref.valid()) {
      continue;
    }
    const auto value = static_cast<uint32_t>(dictionary.readUnsigned(ref));
    const bool bit31 = (value & kInvalidBit) != 0U;
    const bool valid = (cia301 ? !bit31 : bit31) && plainStandardId(value);
    visit(PdoCobId{index, value, valid, value & kIdBits}, receive);
  }
}

/// Whether a valid PDO may have CAN-ID `id`: the profile's range, else not restricted.
bool pdoIdPermitted(const Node& node, bool receive, uint32_t id) {
  const CanIdRange& range = receive ? node.profile().pdo.rpdoCanIds : node.profile().pdo.tpdoCanIds;
  return range.restricts() ? range.contains(id) : !restrictedCanId(id);
}

std::string hex(uint32_t value) {
  char text[16];
  snprintf(text, sizeof(text), "0x%X", static_cast<unsigned>(value));
  return text;
}

}  // namespace

bool restrictedCanId(uint32_t id) {
  return id <= 0x07FU || (id >= 0x101U && id <= 0x180U) || (id >= 0x581U && id <= 0x5FFU) ||
         (id >= 0x601U && id <= 0x67FU) || (id >= 0x6E0U && id <= 0x6FFU) || id >= 0x701U;
}

CanIdSet allowedTransmitIds(const Node& node, bool lss) {
  CanIdSet ids;
  if (lss) {
    ids.add(cob::kLssToMaster);
  }
  const uint8_t nodeId = node.nodeId();
  if (!cob::isValidNodeId(nodeId)) {
    return ids;
  }
  ids.add(cob::kErrorControlBase + nodeId);  // boot-up, heartbeat, guarding: every state
  // CiA 301 7.3.2.2: SDO, EMCY and SYNC in pre-operational and operational, PDOs in
  // operational only.
  const NmtState state = node.state();
  if (state != NmtState::kPreOperational && state != NmtState::kOperational) {
    return ids;
  }
  ids.add(cob::kSdoTxBase + nodeId);
  const od::ObjectDictionary& dictionary = node.dictionary();
  if (dictionary.findObject(kEmcyCobId) == nullptr) {
    ids.add(cob::kEmcyBase + nodeId);
  } else {
    const auto emcy = static_cast<uint32_t>(dictionary.readUnsigned(kEmcyCobId, 0, 0));
    if ((emcy & kInvalidBit) == 0U && plainStandardId(emcy) && !restrictedCanId(emcy & kIdBits)) {
      ids.add(emcy & kIdBits);
    }
  }
  const auto sync = static_cast<uint32_t>(dictionary.readUnsigned(kSyncCobId, 0, 0));
  if ((sync & kSyncProducerBit) != 0U && plainStandardId(sync) &&
      !restrictedCanId(sync & kIdBits)) {
    ids.add(sync & kIdBits);
  }
  if (state != NmtState::kOperational) {
    return ids;
  }
  forEachPdo(node, [&](const PdoCobId& cob, bool receive) {
    if (!receive && cob.valid && pdoIdPermitted(node, false, cob.id)) {
      ids.add(cob.id);
    }
  });
  return ids;
}

std::string checkConfiguredCanIds(const Node& node) {
  if (!cob::isValidNodeId(node.nodeId())) {
    return "";  // silent until LSS gives it a node-id; $NODEID defaults mean nothing yet
  }
  const od::ObjectDictionary& dictionary = node.dictionary();
  if (dictionary.findObject(kSyncCobId) != nullptr) {
    const auto sync = static_cast<uint32_t>(dictionary.readUnsigned(kSyncCobId, 0, 0));
    if (restrictedCanId(sync & kIdBits)) {
      return "SYNC COB-ID " + hex(sync) + " has a restricted CAN-ID";
    }
  }
  if (dictionary.findObject(kEmcyCobId) != nullptr) {
    const auto emcy = static_cast<uint32_t>(dictionary.readUnsigned(kEmcyCobId, 0, 0));
    if ((emcy & kInvalidBit) == 0U && restrictedCanId(emcy & kIdBits)) {
      return "valid EMCY COB-ID " + hex(emcy) + " has a restricted CAN-ID";
    }
  }
  std::string problem;
  forEachPdo(node, [&](const PdoCobId& cob, bool receive) {
    if (problem.empty() && cob.valid && !pdoIdPermitted(node, receive, cob.id)) {
      problem = "valid PDO COB-ID " + hex(cob.value) + " at " + hex(cob.index) +
                ":01 has a CAN-ID a PDO may not use";
    }
  });
  return problem;
}

std::string describeFrame(const CanFrame& frame) {
  char text[64];
  int used = snprintf(text, sizeof(text), frame.extended ? "%08X [%u]" : "%03X [%u]",
                      static_cast<unsigned>(frame.id), static_cast<unsigned>(frame.dlc));
  if (frame.rtr) {
    snprintf(text + used, sizeof(text) - static_cast<size_t>(used), " RTR");
    return text;
  }
  // Bytes beyond the DLC, in parentheses, only when one of them is not zero.
  size_t shown = frame.dlc < sizeof(frame.data) ? frame.dlc : sizeof(frame.data);
  for (size_t i = shown; i < sizeof(frame.data); ++i) {
    if (frame.data[i] != 0U) {
      shown = sizeof(frame.data);
    }
  }
  for (size_t i = 0; i < shown && used > 0 && static_cast<size_t>(used) < 60U; ++i) {
    used += snprintf(text + used, sizeof(text) - static_cast<size_t>(used),
                     i < frame.dlc ? " %02X" : " (%02X)", static_cast<unsigned>(frame.data[i]));
  }
  return text;
}

std::string checkTransmittedFrame(const CanFrame& frame, const CanIdSet& allowed) {
  const std::string what = "transmitted frame " + describeFrame(frame) + ": ";
  if (frame.dlc > 8U) {
    return what + "DLC above 8";
  }
  if (frame.extended) {
    return what + "29-bit identifier";
  }
  if (frame.rtr) {
    return what + "remote frame";
  }
  for (size_t i = frame.dlc; i < sizeof(frame.data); ++i) {
    if (frame.data[i] != 0U) {
      return what + "data byte beyond the DLC is not zero";
    }
  }
  if (!allowed.contains(frame.id)) {
    return what + "CAN-ID not the node's to use";
  }
  const bool sdo = frame.id > cob::kSdoTxBase && frame.id <= cob::kSdoTxBase + 127U;
  const bool errorControl =
      frame.id > cob::kErrorControlBase && frame.id <= cob::kErrorControlBase + 127U;
  if ((sdo || frame.id == cob::kLssToMaster) && frame.dlc != 8U) {
    return what + "SDO and LSS frames have 8 bytes";
  }
  if (errorControl && frame.dlc != 1U) {
    return what + "boot-up, heartbeat and guarding frames have 1 byte";
  }
  return "";
}

}  // namespace costa::fuzz
