#include "frame_rules.hpp"

#include <stdio.h>
#include <string.h>

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

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
constexpr uint16_t kTimeCobId = 0x1012;
constexpr uint32_t kTimeConsumerBit = 0x80000000U;
constexpr uint32_t kTimeProducerBit = 0x40000000U;
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

/// A 32-bit value read in place (the checks call none of the stack's code, which the fuzzer
/// instruments): from the RAM block, or the ROM block for a constant (which holds a `$NODEID`
/// value without the node-id).
/// Calls `visit(index)` for each object of `dictionary` in [first, last], in index order. The
/// same as trying every index of the range, for a rule that looks at existing objects only,
/// at a cost of the objects there (the checks run after every event of every input).
template <typename Visit>
void forEachObjectIn(const od::ObjectDictionary& dictionary, uint16_t first, uint16_t last,
                     Visit visit) {
  const od::Definition& definition = dictionary.definition();
  const od::Object* end = definition.objects + definition.objectCount;
  const od::Object* object =
      std::lower_bound(definition.objects, end, first,
                       [](const od::Object& o, uint16_t index) { return o.index < index; });
  for (; object != end && object->index <= last; ++object) {
    visit(object->index);
  }
}

uint32_t u32At(const od::ObjectDictionary& dictionary, const od::EntryRef& ref) {
  const void* block = ref.inRom() ? dictionary.definition().constants : dictionary.values();
  uint32_t value = 0;
  memcpy(&value, static_cast<const uint8_t*>(block) + ref.offset(), sizeof(value));
  if (ref.inRom() && ref.has(od::kNodeIdRelative)) {
    value += dictionary.nodeId();
  }
  return value;
}

/// Sub-index 0 of `index` when the definition has it as a 32-bit entry, else an invalid ref.
od::EntryRef u32Entry(const od::Definition& definition, uint16_t index) {
  for (size_t i = 0; i < definition.objectCount; ++i) {
    if (definition.objects[i].index == index) {
      const od::EntryRef ref = od::locate(definition, definition.objects[i], 0);
      return ref.valid() && ref.size() == 4U ? ref : od::EntryRef{};
    }
  }
  return od::EntryRef{};
}

/// The COB-ID entries (sub-index 1) of a definition's PDO communication parameters, with
/// whether each is an RPDO's. Worked out once per definition.
const std::vector<std::pair<od::EntryRef, bool>>& pdoCobIdEntries(
    const od::Definition& definition) {
  static std::map<const od::Definition*, std::vector<std::pair<od::EntryRef, bool>>> known;
  const auto found = known.find(&definition);
  if (found != known.end()) {
    return found->second;
  }
  std::vector<std::pair<od::EntryRef, bool>>& entries = known[&definition];
  for (size_t i = 0; i < definition.objectCount; ++i) {
    const od::Object& object = definition.objects[i];
    const bool receive = object.index >= kFirstRpdo && object.index <= kLastRpdo;
    if (!receive && (object.index < kFirstTpdo || object.index > kLastTpdo)) {
      continue;
    }
    const od::EntryRef ref = od::locate(definition, object, 1);
    if (ref.valid() && ref.size() == 4U) {
      entries.emplace_back(ref, receive);
    }
  }
  return entries;
}

/// The SYNC, EMCY and TIME COB-ID entries of a definition (invalid refs when it has none).
struct CobIdEntries {
  od::EntryRef sync;
  od::EntryRef emcy;
  od::EntryRef time;
};

const CobIdEntries& cobIdEntries(const od::Definition& definition) {
  static std::map<const od::Definition*, CobIdEntries> known;
  const auto found = known.find(&definition);
  if (found != known.end()) {
    return found->second;
  }
  return known[&definition] =
             CobIdEntries{u32Entry(definition, kSyncCobId), u32Entry(definition, kEmcyCobId),
                          u32Entry(definition, kTimeCobId)};
}

/// Calls `visit(PdoCobId, receive)` for every PDO communication parameter of the node.
template <typename Visit>
void forEachPdo(const Node& node, Visit visit) {
  const od::ObjectDictionary& dictionary = node.dictionary();
  const bool cia301 = node.profile().pdo.cobIdPolarity == PdoCobIdPolarity::kCia301;
  for (const auto& [ref, receive] : pdoCobIdEntries(dictionary.definition())) {
    const uint32_t value = u32At(dictionary, ref);
    const bool bit31 = (value & kInvalidBit) != 0U;
    const bool valid = (cia301 ? !bit31 : bit31) && plainStandardId(value);
    visit(PdoCobId{ref.index(), value, valid, value & kIdBits}, receive);
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
  forEachObjectIn(dictionary, 0x1201, 0x127F, [&](uint16_t index) {
    // An additional server's responses (answers under way when it was reconfigured included).
    const uint32_t response = static_cast<uint32_t>(dictionary.readUnsigned(index, 2, ~0U));
    if (plainStandardId(response & ~kInvalidBit) && !restrictedCanId(response & kIdBits)) {
      ids.add(response & kIdBits);
    }
  });
  const CobIdEntries& cobIds = cobIdEntries(dictionary.definition());
  if (!cobIds.emcy.valid()) {
    ids.add(cob::kEmcyBase + nodeId);
  } else {
    const uint32_t emcy = u32At(dictionary, cobIds.emcy);
    if ((emcy & kInvalidBit) == 0U && plainStandardId(emcy) && !restrictedCanId(emcy & kIdBits)) {
      ids.add(emcy & kIdBits);
    }
  }
  const uint32_t sync = cobIds.sync.valid() ? u32At(dictionary, cobIds.sync) : 0U;
  if ((sync & kSyncProducerBit) != 0U && plainStandardId(sync) &&
      !restrictedCanId(sync & kIdBits)) {
    ids.add(sync & kIdBits);
  }
  const uint32_t time = cobIds.time.valid() ? u32At(dictionary, cobIds.time) : 0U;
  if ((time & kTimeProducerBit) != 0U && plainStandardId(time) &&
      !restrictedCanId(time & kIdBits)) {
    ids.add(time & kIdBits);
  }
  if (dictionary.readUnsigned(0x1300, 0, 0) == 1U) {
    ids.add(0x001);  // GFC (CiA 304) where 0x1300 makes it valid
  }
  if (state != NmtState::kOperational) {
    return ids;
  }
  forEachPdo(node, [&](const PdoCobId& cob, bool receive) {
    if (!receive && cob.valid && pdoIdPermitted(node, false, cob.id)) {
      ids.add(cob.id);
    }
  });
  // Transmit SRDOs (CiA 304): their two COB-IDs, which CiA 304 keeps in 0x101..0x180.
  forEachObjectIn(dictionary, 0x1301, 0x1340, [&](uint16_t index) {
    if (dictionary.readUnsigned(index, 1, 0) == 1U) {
      for (uint8_t sub = 5; sub <= 6; ++sub) {
        const auto id = static_cast<uint32_t>(dictionary.readUnsigned(index, sub, 0));
        if (id >= 0x101U && id <= 0x180U) {
          ids.add(id);
        }
      }
    }
  });
  return ids;
}

std::string checkConfiguredCanIds(const Node& node) {
  if (!cob::isValidNodeId(node.nodeId())) {
    return "";  // silent until LSS gives it a node-id; $NODEID defaults mean nothing yet
  }
  const od::ObjectDictionary& dictionary = node.dictionary();
  const CobIdEntries& cobIds = cobIdEntries(dictionary.definition());
  if (cobIds.sync.valid()) {
    const uint32_t sync = u32At(dictionary, cobIds.sync);
    if (restrictedCanId(sync & kIdBits)) {
      return "SYNC COB-ID " + hex(sync) + " has a restricted CAN-ID";
    }
  }
  if (cobIds.emcy.valid()) {
    const uint32_t emcy = u32At(dictionary, cobIds.emcy);
    if ((emcy & kInvalidBit) == 0U && restrictedCanId(emcy & kIdBits)) {
      return "valid EMCY COB-ID " + hex(emcy) + " has a restricted CAN-ID";
    }
  }
  const od::Object* consumer = dictionary.findObject(0x1028);
  for (uint8_t sub = 1; consumer != nullptr && sub != 0U; ++sub) {
    const od::EntryRef ref = dictionary.find(0x1028, sub);
    if (!ref.valid()) {
      break;
    }
    const uint32_t entry = u32At(dictionary, ref);
    if ((entry & kInvalidBit) == 0U &&
        (restrictedCanId(entry & kIdBits) || !plainStandardId(entry))) {
      return "valid EMCY consumer entry " + hex(entry) + " has a restricted or 29-bit CAN-ID";
    }
  }
  std::string found;
  forEachObjectIn(dictionary, 0x1201, 0x127F, [&](uint16_t index) {
    for (uint8_t sub = 1; sub <= 2U && found.empty(); ++sub) {
      const auto cob = static_cast<uint32_t>(dictionary.readUnsigned(index, sub, kInvalidBit));
      if ((cob & kInvalidBit) == 0U && (restrictedCanId(cob & kIdBits) || !plainStandardId(cob))) {
        found = "valid SDO server COB-ID " + hex(cob) + " at " + hex(index) +
                " has a restricted or 29-bit CAN-ID";
      }
    }
  });
  forEachObjectIn(dictionary, 0x1301, 0x1340, [&](uint16_t index) {
    const uint64_t direction = dictionary.readUnsigned(index, 1, 0);
    const uint64_t normal = dictionary.readUnsigned(index, 5, 0x101);
    const uint64_t inverted = dictionary.readUnsigned(index, 6, 0x102);
    if (found.empty() && direction != 0U &&
        (normal < 0x101U || normal > 0x180U || (normal & 1U) == 0U || inverted < 0x101U ||
         inverted > 0x180U || (inverted & 1U) != 0U)) {
      found = "SRDO " + hex(index) + " has a COB-ID outside 0x101..0x180 or of the wrong parity";
    }
  });
  if (!found.empty()) {
    return found;
  }
  if (cobIds.time.valid()) {
    const uint32_t time = u32At(dictionary, cobIds.time);
    const bool used = (time & (kTimeConsumerBit | kTimeProducerBit)) != 0U;
    if (used && (restrictedCanId(time & kIdBits) || !plainStandardId(time))) {
      return "TIME COB-ID " + hex(time) + " in use has a restricted or 29-bit CAN-ID";
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

namespace {

/// Why `frame` may not be transmitted, or null.
const char* transmittedFrameFault(const CanFrame& frame, const CanIdSet& allowed) {
  if (frame.dlc > 8U) {
    return "DLC above 8";
  }
  if (frame.extended) {
    return "29-bit identifier";
  }
  if (frame.rtr) {
    return "remote frame";
  }
  for (size_t i = frame.dlc; i < sizeof(frame.data); ++i) {
    if (frame.data[i] != 0U) {
      return "data byte beyond the DLC is not zero";
    }
  }
  if (!allowed.contains(frame.id)) {
    return "CAN-ID not the node's to use";
  }
  const bool sdo = frame.id > cob::kSdoTxBase && frame.id <= cob::kSdoTxBase + 127U;
  const bool errorControl =
      frame.id > cob::kErrorControlBase && frame.id <= cob::kErrorControlBase + 127U;
  if ((sdo || frame.id == cob::kLssToMaster) && frame.dlc != 8U) {
    return "SDO and LSS frames have 8 bytes";
  }
  if (frame.id == 0x001U && frame.dlc != 0U) {
    return "GFC has no data";
  }
  if (errorControl && frame.dlc != 1U) {
    return "boot-up, heartbeat and guarding frames have 1 byte";
  }
  return nullptr;
}

}  // namespace

std::string checkTransmittedFrame(const CanFrame& frame, const CanIdSet& allowed) {
  const char* fault = transmittedFrameFault(frame, allowed);  // the text only for a fault
  return fault == nullptr ? std::string()
                          : "transmitted frame " + describeFrame(frame) + ": " + fault;
}

}  // namespace costa::fuzz
