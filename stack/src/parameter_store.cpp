#include "costa/parameter_store.hpp"

#include "costa/od/bytes.hpp"

namespace costa {
namespace {

/// Moves `*ref` to the next sub-index, in dictionary order, of a row of storage group `group`
/// that has every attribute of `attributes`; to the first one when `*ref` is not valid. False,
/// and `*ref` not valid, past the last. A row of another group costs one test, however many
/// sub-indices it has.
[[gnu::noinline]] bool nextInGroup(const od::Definition& definition, uint8_t group,
                                   uint8_t attributes, od::EntryRef* ref) noexcept {
  size_t objectAt = 0;
  size_t rowAt = 0;
  unsigned step = 0;
  if (ref->valid()) {  // the sub-index after it
    objectAt = static_cast<size_t>(ref->object - definition.objects);
    rowAt = static_cast<size_t>(ref->row - od::rowsOf(definition, *ref->object));
    step = static_cast<unsigned>(ref->sub - ref->row->subIndex) + 1U;
  }
  for (; objectAt < definition.objectCount; ++objectAt) {
    const od::Object& object = definition.objects[objectAt];
    const od::SubEntry* rows = od::rowsOf(definition, object);
    for (; rowAt < object.rowCount; ++rowAt) {
      const od::SubEntry& row = rows[rowAt];
      if (row.group == group && (row.attributes & attributes) == attributes && step < row.count) {
        *ref = od::EntryRef::at(object, row, static_cast<uint8_t>(row.subIndex + step));
        return true;
      }
      step = 0;  // the next row from its first sub-index
    }
    rowAt = 0;
  }
  *ref = od::EntryRef{};
  return false;
}

/// Calls `visit(ref, address, size)` for every RAM entry of `group` in dictionary order; stops
/// at the first false.
template <typename Visit>
bool forEachStoredEntry(od::ObjectDictionary& dictionary, uint8_t group, Visit visit) noexcept {
  for (od::EntryRef ref; nextInGroup(dictionary.definition(), group, 0, &ref);) {
    uint8_t* address = dictionary.ramAddress(ref);
    if (address != nullptr && ref.size() != 0U &&
        !visit(ref, address, static_cast<size_t>(ref.size()))) {
      return false;
    }
  }
  return true;
}

// `$NODEID` entries (CiA 306: the default is `$NODEID + n`) follow the node-id across a save
// and a load with another node-id. A number is stored without the node-id and gets the node-id
// of the load. A COB-ID (an UNSIGNED32 of 0x1000..0x1FFF) follows the node-id only while its
// CAN-ID is its default's: it is stored with the default's CAN-ID without the node-id (the base),
// to which a load adds the node-id. A COB-ID whose CAN-ID a master moved elsewhere is stored and
// loaded as it is, so that a node-id change never moves it onto a CAN-ID of another node or one
// CiA 301 restricts; one moved onto the base itself is stored with bit 28 set, which a valid
// 11-bit COB-ID never has, so that it does not read back as one at its default. A COB-ID's flags
// never change; a 29-bit COB-ID (bit 29) and one with bits 11..28 set are stored as they are.
constexpr uint32_t kStandardCanId = 0x7FFU;
constexpr uint32_t kAsItIs = 0x3FFFF800U;        ///< bit 29, or bits 11..28 (reserved)
constexpr uint32_t kMovedOntoBase = 1UL << 28U;  ///< in a stored image only

/// Whether the `$NODEID` entry `ref` is a COB-ID; if so, `*base` is its default's CAN-ID without
/// the node-id.
bool isCobId(const od::ObjectDictionary& dictionary, const od::EntryRef& ref,
             uint32_t* base) noexcept {
  if (ref.type() != od::DataType::kUnsigned32 || ref.index() < 0x1000U || ref.index() > 0x1FFFU) {
    return false;
  }
  uint8_t bytes[4] = {};
  od::copyDefault(dictionary.definition(), ref, bytes);
  copyBytes(base, bytes, sizeof(*base));
  *base &= kStandardCanId;
  return true;
}

/// What a save stores of the `$NODEID` entry `ref` whose value is `value`.
uint64_t storedForm(const od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                    uint64_t value) noexcept {
  const uint8_t nodeId = dictionary.nodeId();
  uint32_t base = 0;
  if (!isCobId(dictionary, ref, &base)) {
    return value - nodeId;
  }
  const auto cob = static_cast<uint32_t>(value);
  const uint32_t canId = cob & kStandardCanId;
  if ((cob & kAsItIs) != 0U) {
    return cob;
  }
  if (canId == ((base + nodeId) & kStandardCanId)) {
    return (cob & ~kStandardCanId) | base;  // at its default's: follows
  }
  return canId == base ? cob | kMovedOntoBase : cob;
}

/// The value of the `$NODEID` entry `ref` that a load read as `stored` (see storedForm()).
uint64_t loadedForm(const od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                    uint64_t stored) noexcept {
  const uint8_t nodeId = dictionary.nodeId();
  uint32_t base = 0;
  if (!isCobId(dictionary, ref, &base)) {
    return stored + nodeId;
  }
  const auto cob = static_cast<uint32_t>(stored);
  if ((cob & kStandardCanId) != base) {
    return cob;
  }
  if ((cob & kAsItIs) == 0U) {
    return (cob & ~kStandardCanId) | ((base + nodeId) & kStandardCanId);
  }
  return (cob & kAsItIs) == kMovedOntoBase ? cob & ~kMovedOntoBase : cob;
}

/// Whether the region `id` holds a `$NODEID` COB-ID: the one kind of entry whose stored form
/// format version 2 changed (version 1 stored it without the node-id over all 32 bits).
bool holdsNodeIdCobId(const od::ObjectDictionary& dictionary, uint16_t id) noexcept {
  if (id > UINT8_MAX) {
    return false;  // a record region's id is never a group's (kRecordRegion)
  }
  const auto group = static_cast<uint8_t>(id);
  for (od::EntryRef ref; nextInGroup(dictionary.definition(), group, od::kNodeIdRelative, &ref);) {
    uint32_t base = 0;
    if (isCobId(dictionary, ref, &base)) {
      return true;
    }
  }
  return false;
}

/// Adds the node-id to the `$NODEID` entries of `group` after a load (see storedForm()), then
/// gives each its default if the dictionary refuses it (see load()).
void addNodeIdAfterLoad(od::ObjectDictionary& dictionary, uint8_t group) noexcept {
  for (od::EntryRef ref; nextInGroup(dictionary.definition(), group, od::kNodeIdRelative, &ref);) {
    if (dictionary.ramAddress(ref) != nullptr) {
      dictionary.storeUnsigned(ref, loadedForm(dictionary, ref, dictionary.readUnsigned(ref)));
      dictionary.restoreDefaultIfRefused(ref);
    }
  }
}

// Ranks of what a slot holds: the higher one is kept, the lower one is written next.
constexpr int kRankBlank = 0;
constexpr int kRankDamaged = 1;
constexpr int kRankForeign = 2;
constexpr int kRankCurrent = 3;

}  // namespace

const char* toString(StoreResult result) noexcept {
  switch (result) {
    case StoreResult::kOk: return "ok";
    case StoreResult::kNoImage: return "no image";
    case StoreResult::kCorrupt: return "corrupt";
    case StoreResult::kIncompatible: return "incompatible";
    case StoreResult::kMediumError: return "medium error";
    case StoreResult::kUnknownGroup: return "unknown group";
    case StoreResult::kTooLong: return "too long";
    case StoreResult::kNotLaidOut: return "not laid out";
  }
  return "?";
}

bool ParameterStore::isCurrent(const Region& region, size_t slot,
                               const SlotInfo& info) const noexcept {
  const ImageHeader& header = info.header;
  if (info.state != SlotState::kIntact || header.region != region.id ||
      header.location != slotOffset(region, slot)) {
    return false;
  }
  // A version 1 image means the same as a version 2 one unless it holds a $NODEID COB-ID.
  if (header.formatVersion != kImageFormatVersion &&
      (header.formatVersion != 1U || holdsNodeIdCobId(dictionary_, region.id))) {
    return false;
  }
  if (header.kind == ImageKind::kDefaults) {
    return header.payloadLength == 0U;
  }
  if (header.kind != ImageKind::kValues || header.layout != region.layout) {
    return false;
  }
  const bool isRecord = (region.id & kRecordRegion) != 0U;
  return isRecord ? header.payloadLength <= region.payloadCapacity
                  : header.payloadLength == region.payloadCapacity;
}

int ParameterStore::rank(const Region& region, size_t slot, const SlotInfo& info) const noexcept {
  switch (info.state) {
    case SlotState::kIntact: return isCurrent(region, slot, info) ? kRankCurrent : kRankForeign;
    case SlotState::kDamaged: return kRankDamaged;
    case SlotState::kBlank:
    case SlotState::kUnreadable: break;
  }
  return kRankBlank;
}

bool ParameterStore::examine(const Region& region, Examination* out) noexcept {
  for (size_t slot = 0; slot < 2U; ++slot) {
    out->slots[slot] = inspectSlot(storage_, slotOffset(region, slot), region.slotSize);
    if (out->slots[slot].state == SlotState::kUnreadable) {
      return false;
    }
  }
  const int rank0 = rank(region, 0, out->slots[0]);
  const int rank1 = rank(region, 1, out->slots[1]);
  const bool secondIsNewer =
      isNewerSequence(out->slots[1].header.sequence, out->slots[0].header.sequence);
  // Slot 0 is kept only when it holds the better image: so that, among equals, slot 0 is the
  // one written (the first save goes to slot 0).
  const bool firstIsBetter =
      rank0 > rank1 || (rank0 == kRankCurrent && rank1 == kRankCurrent && !secondIsNewer);
  out->kept = firstIsBetter ? 0U : 1U;
  const SlotInfo& kept = out->slots[out->kept];
  switch (out->kept == 0U ? rank0 : rank1) {
    case kRankCurrent:
      out->verdict =
          kept.header.kind == ImageKind::kValues ? StoreResult::kOk : StoreResult::kNoImage;
      break;
    case kRankForeign: out->verdict = StoreResult::kIncompatible; break;
    case kRankDamaged: out->verdict = StoreResult::kCorrupt; break;
    default: out->verdict = StoreResult::kNoImage; break;
  }
  out->nextSequence = kept.state == SlotState::kIntact ? kept.header.sequence + 1U : 1U;
  return true;
}

StoreResult ParameterStore::writeImage(const Region& region, ImageKind kind, const uint8_t* data,
                                       size_t length) noexcept {
  Examination examination;
  if (!examine(region, &examination)) {
    return StoreResult::kMediumError;
  }
  const size_t target = 1U - examination.kept;
  const size_t offset = slotOffset(region, target);
  const bool isRecord = (region.id & kRecordRegion) != 0U;
  const bool fromDictionary = kind == ImageKind::kValues && !isRecord;
  ImageHeader header{};
  header.formatVersion = kImageFormatVersion;
  header.kind = kind;
  header.region = region.id;
  header.layout = region.layout;
  header.location = static_cast<uint32_t>(offset);
  header.payloadLength = static_cast<uint32_t>(fromDictionary ? region.payloadCapacity : length);
  header.sequence = examination.nextSequence;

  ImageWriter writer(storage_, offset, region.slotSize);
  bool ok = writer.begin(header);
  if (ok && fromDictionary) {
    // A `$NODEID` entry is written in its stored form (storedForm()) and its value put back.
    od::ObjectDictionary& dictionary = dictionary_;
    ok = forEachStoredEntry(
        dictionary, static_cast<uint8_t>(region.id),
        [&writer, &dictionary](const od::EntryRef& ref, const uint8_t* address, size_t size) {
          if (!ref.has(od::kNodeIdRelative)) {
            return writer.append(address, size);
          }
          const uint64_t value = dictionary.readUnsigned(ref);
          dictionary.storeUnsigned(ref, storedForm(dictionary, ref, value));
          const bool appended = writer.append(address, size);
          dictionary.storeUnsigned(ref, value);
          return appended;
        });
  } else if (ok && length != 0U) {
    ok = writer.append(data, length);
  }
  return ok && writer.finish() ? StoreResult::kOk : StoreResult::kMediumError;
}

StoreResult ParameterStore::save(uint8_t group) noexcept {
  const Region* region = nullptr;
  const StoreResult found = findRegion(group, &region);
  if (found != StoreResult::kOk) {
    return found;
  }
  return writeImage(*region, ImageKind::kValues, nullptr, 0);
}

StoreResult ParameterStore::saveGroups(uint32_t groups) noexcept {
  StoreResult result = StoreResult::kUnknownGroup;
  for (uint8_t group = 1; group < 32U; ++group) {
    if ((groups & (uint32_t{1} << group)) == 0U || !hasGroup(group)) {
      continue;
    }
    result = save(group);
    if (result != StoreResult::kOk) {
      return result;
    }
  }
  return result;
}

StoreResult ParameterStore::invalidateGroups(uint32_t groups) noexcept {
  StoreResult result = StoreResult::kUnknownGroup;
  for (uint8_t group = 1; group < 32U; ++group) {
    if ((groups & (uint32_t{1} << group)) == 0U || !hasGroup(group)) {
      continue;
    }
    result = invalidate(group);
    if (result != StoreResult::kOk) {
      return result;
    }
  }
  return result;
}

StoreResult ParameterStore::invalidate(uint8_t group) noexcept {
  const Region* region = nullptr;
  const StoreResult found = findRegion(group, &region);
  return found != StoreResult::kOk ? found : writeImage(*region, ImageKind::kDefaults, nullptr, 0);
}

StoreResult ParameterStore::load(uint8_t group) noexcept {
  const Region* region = nullptr;
  const StoreResult found = findRegion(group, &region);
  if (found != StoreResult::kOk) {
    return found;
  }
  Examination examination;
  if (!examine(*region, &examination)) {
    return StoreResult::kMediumError;
  }
  if (examination.verdict != StoreResult::kOk) {
    return examination.verdict;
  }
  ImageReader reader(storage_, slotOffset(*region, examination.kept),
                     examination.slots[examination.kept].header);
  // A refused value gets its default as it arrives (a `$NODEID` one once it has its node-id);
  // a copy that fails on the way restores every default of the group anyway.
  od::ObjectDictionary& dictionary = dictionary_;
  const bool copied = forEachStoredEntry(
      dictionary, group,
      [&reader, &dictionary](const od::EntryRef& ref, uint8_t* address, size_t size) {
        if (!reader.read(address, size)) {
          return false;
        }
        if (!ref.has(od::kNodeIdRelative)) {
          dictionary.restoreDefaultIfRefused(ref);
        }
        return true;
      });
  if (copied && reader.matches()) {
    addNodeIdAfterLoad(dictionary_, group);
    return StoreResult::kOk;
  }
  // The medium changed since it was checked: never leave a mix of old and new values.
  dictionary_.restoreGroupDefaults(group);
  return copied ? StoreResult::kCorrupt : StoreResult::kMediumError;
}

StoreResult ParameterStore::saveRecord(uint8_t recordId, const uint8_t* data,
                                       size_t length) noexcept {
  const Region* region = nullptr;
  const StoreResult found = findRegion(recordRegion(recordId), &region);
  if (found != StoreResult::kOk) {
    return found;
  }
  if (length > region->payloadCapacity) {
    return StoreResult::kTooLong;
  }
  return writeImage(*region, ImageKind::kValues, data, length);
}

StoreResult ParameterStore::invalidateRecord(uint8_t recordId) noexcept {
  const Region* region = nullptr;
  const StoreResult found = findRegion(recordRegion(recordId), &region);
  return found != StoreResult::kOk ? found : writeImage(*region, ImageKind::kDefaults, nullptr, 0);
}

StoreResult ParameterStore::loadRecord(uint8_t recordId, uint8_t* buffer, size_t capacity,
                                       size_t* length) noexcept {
  *length = 0;
  const Region* region = nullptr;
  const StoreResult found = findRegion(recordRegion(recordId), &region);
  if (found != StoreResult::kOk) {
    return found;
  }
  Examination examination;
  if (!examine(*region, &examination)) {
    return StoreResult::kMediumError;
  }
  if (examination.verdict != StoreResult::kOk) {
    return examination.verdict;
  }
  const ImageHeader& header = examination.slots[examination.kept].header;
  if (header.payloadLength > capacity) {
    return StoreResult::kTooLong;
  }
  ImageReader reader(storage_, slotOffset(*region, examination.kept), header);
  if (!reader.read(buffer, header.payloadLength)) {
    return StoreResult::kMediumError;
  }
  if (!reader.matches()) {
    return StoreResult::kCorrupt;
  }
  *length = header.payloadLength;
  return StoreResult::kOk;
}

}  // namespace costa
