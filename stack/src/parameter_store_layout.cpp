#include "costa/parameter_store.hpp"

namespace costa {
namespace {

/// True when `value` does not fit in 32 bits (the size of stored offsets). Takes 64 bits so
/// that the same code compiles without range warnings where size_t has 32.
bool exceeds32Bits(uint64_t value) noexcept {
  return (value >> 32U) != 0U;
}

/// The bytes of a slot: an image header and `capacity` bytes of payload, rounded up to a
/// multiple of `alignment` (both below 2^32). Divides 32 bits only (no 64-bit division on small
/// cores); a header and payload beyond 32 bits are returned as they are, too large anyway.
uint64_t slotBytes(uint64_t capacity, uint64_t alignment) noexcept {
  const uint64_t value = kImageHeaderSize + capacity;
  if (exceeds32Bits(value)) {
    return value;
  }
  const uint32_t rest = static_cast<uint32_t>(value) % static_cast<uint32_t>(alignment);
  return rest == 0U ? value : value + (alignment - rest);
}

/// A stored group and the bytes its RAM values take.
struct GroupBytes {
  uint8_t group;
  uint64_t bytes;
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
  if ((row.attributes & od::kInRom) == 0U && row.type != od::DataType::kDomain) {
    groups[at].bytes += static_cast<uint64_t>(row.size) * row.count;
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
  uint64_t offset = 0;
  // Offsets are stored as 32 bits: bounding every term keeps the 64-bit sums exact.
  const auto place = [&](uint16_t id, uint32_t layout, size_t capacity) {
    if (*count == kMaxRegions || exceeds32Bits(capacity) || exceeds32Bits(slotAlignment_)) {
      return false;
    }
    const uint64_t slotSize = slotBytes(capacity, slotAlignment_);
    if (exceeds32Bits(offset + 2U * slotSize)) {
      return false;
    }
    if (regions != nullptr) {
      Region& region = regions[*count];
      region.id = id;
      region.layout = layout;
      region.offset = static_cast<size_t>(offset);
      region.slotSize = static_cast<size_t>(slotSize);
      region.payloadCapacity = capacity;
    }
    ++*count;
    offset += 2U * slotSize;
    return true;
  };
  GroupBytes groups[kMaxRegions] = {};
  const size_t groupCount = collectGroups(dictionary_.definition(), groups, kMaxRegions);
  if (groupCount == SIZE_MAX) {
    return SIZE_MAX;
  }
  for (size_t i = 0; i < groupCount; ++i) {
    if (exceeds32Bits(groups[i].bytes) || !place(groups[i].group, dictionary_.definition().layoutId,
                                                 static_cast<size_t>(groups[i].bytes))) {
      return SIZE_MAX;
    }
  }
  // Records sit at the end of the medium, so that another set of groups (a firmware update that
  // stores one more parameter) never moves them: the LSS node-id and bit rate survive it.
  const uint64_t groupsEnd = offset;
  uint64_t recordBytes = 0;
  for (size_t i = 0; i < recordCount_; ++i) {
    if (exceeds32Bits(records_[i].maxLength) || exceeds32Bits(slotAlignment_)) {
      return SIZE_MAX;
    }
    recordBytes += 2U * slotBytes(records_[i].maxLength, slotAlignment_);
  }
  const uint64_t end = exceeds32Bits(storage_.size()) ? 0xFFFFFFFFU : storage_.size();
  if (end >= groupsEnd + recordBytes) {
    const auto start = static_cast<uint32_t>(end - recordBytes);
    offset = start - start % static_cast<uint32_t>(slotAlignment_);  // not below groupsEnd
  }
  for (size_t i = 0; i < recordCount_; ++i) {
    if (!place(recordRegion(records_[i].id), 0U, records_[i].maxLength)) {
      return SIZE_MAX;
    }
  }
  return static_cast<size_t>(groupsEnd + recordBytes);
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
