#include "costa/parameter_store.hpp"

namespace costa {
namespace {

/// True when `value` does not fit in 32 bits (the size of stored offsets). Takes 64 bits so
/// that the same code compiles without range warnings where size_t has 32.
bool exceeds32Bits(uint64_t value) noexcept {
  return (value >> 32U) != 0U;
}

uint64_t roundUp(uint64_t value, uint64_t alignment) noexcept {
  return (value + alignment - 1U) / alignment * alignment;
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
    const uint64_t slotSize = roundUp(kImageHeaderSize + static_cast<uint64_t>(capacity),
                                      static_cast<uint64_t>(slotAlignment_));
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
  // Which groups occur, in one pass over the dictionary.
  uint32_t present[8] = {};
  const od::Definition& definition = dictionary_.definition();
  for (size_t i = 0; i < definition.objectCount; ++i) {
    const od::Object& object = definition.objects[i];
    for (size_t r = 0; r < object.rowCount; ++r) {
      const uint8_t group = object.rows[r].group;
      present[group / 32U] |= uint32_t{1} << (group % 32U);
    }
  }
  for (unsigned group = 1; group <= UINT8_MAX; ++group) {
    if ((present[group / 32U] & (uint32_t{1} << (group % 32U))) != 0U &&
        !place(static_cast<uint16_t>(group), definition.layoutId,
               groupPayloadLength(static_cast<uint8_t>(group)))) {
      return SIZE_MAX;
    }
  }
  for (size_t i = 0; i < recordCount_; ++i) {
    if (!place(recordRegion(records_[i].id), 0U, records_[i].maxLength)) {
      return SIZE_MAX;
    }
  }
  return static_cast<size_t>(offset);
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
