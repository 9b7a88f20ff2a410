#include "costa/parameter_store.hpp"

#include "costa/shift_arithmetic.hpp"

namespace costa {
namespace {

/// `value` in the 32 bits of a stored offset: false when it does not fit. Takes 64 bits so that
/// the same code compiles without range warnings where size_t has 32.
bool fits32(uint64_t value, uint32_t* out) noexcept {
  *out = static_cast<uint32_t>(value);
  return (value >> 32U) == 0U;
}

/// The bytes of a slot: an image header and `payload` bytes, rounded up to a multiple of
/// `alignment` (not 0). False when that does not fit in 32 bits.
bool slotBytes(uint32_t payload, uint32_t alignment, uint32_t* bytes) noexcept {
  uint32_t value = 0;
  if (__builtin_add_overflow(payload, uint32_t{kImageHeaderSize}, &value)) {
    return false;
  }
  const uint32_t rest = divide(value, alignment).remainder;
  return !__builtin_add_overflow(value, rest == 0U ? 0U : alignment - rest, bytes);
}

/// A stored group and the bytes its RAM values take (at most UINT32_MAX: more cannot be laid
/// out).
struct GroupBytes {
  uint8_t group;
  uint32_t bytes;
};

/// Adds `row` to the group list kept in order of group id (the regions' order). False when the
/// row's group is new and the list is full.
bool addRow(const od::SubEntry& row, GroupBytes* groups, size_t* count, size_t capacity) noexcept {
  size_t at = 0;
  while (at < *count && groups[at].group < row.group) {
    ++at;
  }
  if (at == *count || groups[at].group != row.group) {
    if (*count == capacity) {
      return false;
    }
    for (size_t k = *count; k > at; --k) {
      groups[k] = groups[k - 1U];
    }
    groups[at] = GroupBytes{row.group, 0};
    ++*count;
  }
  if ((row.attributes & od::kInRom) == 0U && row.type != od::DataType::kDomain &&
      __builtin_add_overflow(groups[at].bytes, uint32_t{row.size} * row.count, &groups[at].bytes)) {
    groups[at].bytes = UINT32_MAX;
  }
  return true;
}

/// The groups that occur and the bytes each stores, in one pass over the rows; SIZE_MAX when
/// there are more than `capacity`.
size_t collectGroups(const od::Definition& definition, GroupBytes* groups,
                     size_t capacity) noexcept {
  size_t count = 0;
  for (size_t i = 0; i < definition.objectCount; ++i) {
    const od::Object& object = definition.objects[i];
    const od::SubEntry* rows = od::rowsOf(definition, object);
    for (size_t r = 0; r < object.rowCount; ++r) {
      if (rows[r].group != od::kGroupNone && !addRow(rows[r], groups, &count, capacity)) {
        return SIZE_MAX;
      }
    }
  }
  return count;
}

}  // namespace

ParameterStore::ParameterStore(od::ObjectDictionary& dictionary, NvStorage& storage,
                               size_t slotAlignment) noexcept
    : dictionary_(dictionary),
      storage_(storage),
      slotAlignment_(slotAlignment == 0U ? 1U : slotAlignment) {}

bool ParameterStore::reserveRecord(uint8_t recordId, size_t maxLength) noexcept {
  if (recordCount_ == kMaxRecords) {
    return false;
  }
  size_t at = 0;
  while (at < recordCount_ && records_[at].id < recordId) {
    ++at;
  }
  if (at < recordCount_ && records_[at].id == recordId) {
    return false;
  }
  for (size_t i = recordCount_; i > at; --i) {
    records_[i] = records_[i - 1U];
  }
  records_[at] = Record{recordId, maxLength};
  ++recordCount_;
  laidOut_ = false;
  return true;
}

bool ParameterStore::hasGroup(uint8_t group) const noexcept {
  if (group == od::kGroupNone) {
    return false;
  }
  if (laidOut_) {  // the regions are the groups that occur: no pass over the dictionary
    const Region* region = nullptr;
    return findRegion(group, &region) == StoreResult::kOk;
  }
  return groupPayloadLength(group) != SIZE_MAX;
}

size_t ParameterStore::groupPayloadLength(uint8_t group) const noexcept {
  size_t length = 0;
  bool present = false;
  for (const od::EntryRef& ref : od::Entries(dictionary_.definition())) {
    if (ref.group() == group) {
      present = true;
      if (dictionary_.ramAddress(ref) != nullptr) {
        length += ref.size();
      }
    }
  }
  return present ? length : SIZE_MAX;
}

size_t ParameterStore::computeLayout(Region* regions, size_t* count) const noexcept {
  *count = 0;
  // Offsets and sizes are stored as 32 bits: any sum beyond them refuses the layout.
  uint32_t alignment = 0;
  if (!fits32(slotAlignment_, &alignment)) {
    return SIZE_MAX;
  }
  uint32_t offset = 0;
  const auto place = [&](uint16_t id, uint32_t layout, size_t capacity) {
    uint32_t payload = 0;
    uint32_t slotSize = 0;
    uint32_t end = 0;
    if (*count == kMaxRegions || !fits32(capacity, &payload) ||
        !slotBytes(payload, alignment, &slotSize) ||
        __builtin_add_overflow(slotSize, slotSize, &end) ||
        __builtin_add_overflow(end, offset, &end)) {
      return false;
    }
    if (regions != nullptr) {
      Region& region = regions[*count];
      region.id = id;
      region.layout = layout;
      region.offset = offset;
      region.slotSize = slotSize;
      region.payloadCapacity = capacity;
    }
    ++*count;
    offset = end;
    return true;
  };
  GroupBytes groups[kMaxRegions] = {};
  const size_t groupCount = collectGroups(dictionary_.definition(), groups, kMaxRegions);
  if (groupCount == SIZE_MAX) {
    return SIZE_MAX;
  }
  for (size_t i = 0; i < groupCount; ++i) {
    if (!place(groups[i].group, dictionary_.definition().layoutId, groups[i].bytes)) {
      return SIZE_MAX;
    }
  }
  // Records sit at the end of the medium, so that another set of groups (a firmware update that
  // stores one more parameter) never moves them: the LSS node-id and bit rate survive it.
  const uint32_t groupsEnd = offset;
  uint32_t needed = groupsEnd;
  for (size_t i = 0; i < recordCount_; ++i) {
    uint32_t payload = 0;
    uint32_t slotSize = 0;
    if (!fits32(records_[i].maxLength, &payload) || !slotBytes(payload, alignment, &slotSize) ||
        __builtin_add_overflow(needed, slotSize, &needed) ||
        __builtin_add_overflow(needed, slotSize, &needed)) {
      return SIZE_MAX;
    }
  }
  uint32_t end = 0;
  if (!fits32(storage_.size(), &end)) {
    end = UINT32_MAX;
  }
  if (end >= needed) {
    const uint32_t start = end - (needed - groupsEnd);
    offset = start - divide(start, alignment).remainder;  // not below groupsEnd
  }
  for (size_t i = 0; i < recordCount_; ++i) {
    if (!place(recordRegion(records_[i].id), 0U, records_[i].maxLength)) {
      return SIZE_MAX;
    }
  }
  return needed;
}

size_t ParameterStore::requiredSize() const noexcept {
  size_t count = 0;
  return computeLayout(nullptr, &count);
}

bool ParameterStore::layOut() noexcept {
  laidOut_ = false;
  const size_t required = computeLayout(regions_, &regionCount_);
  if (required == SIZE_MAX || required > storage_.size()) {
    regionCount_ = 0;
    return false;
  }
  laidOut_ = true;
  return true;
}

StoreResult ParameterStore::findRegion(uint16_t id, const Region** region) const noexcept {
  if (!laidOut_) {
    return StoreResult::kNotLaidOut;
  }
  for (size_t i = 0; i < regionCount_; ++i) {
    if (regions_[i].id == id) {
      *region = &regions_[i];
      return StoreResult::kOk;
    }
  }
  return StoreResult::kUnknownGroup;
}

}  // namespace costa
