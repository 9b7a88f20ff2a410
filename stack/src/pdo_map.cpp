#include "costa/pdo_map.hpp"

namespace costa {
namespace {

constexpr uint16_t kFirstDummy = 0x0002;  // INTEGER8
constexpr uint16_t kLastDummy = 0x0007;   // UNSIGNED32

uint8_t dummyBytes(uint16_t index) noexcept {
  switch (index) {
    case 0x0002:
    case 0x0005: return 1;
    case 0x0003:
    case 0x0006: return 2;
    default: return 4;  // 0x0004, 0x0007
  }
}

}  // namespace

AbortCode PdoMap::checkEntry(const od::ObjectDictionary& dictionary, uint32_t value,
                             PdoDirection direction) noexcept {
  if (value == 0U) {
    return AbortCode::kNone;
  }
  const auto index = static_cast<uint16_t>(value >> 16U);
  const auto subIndex = static_cast<uint8_t>(value >> 8U);
  const auto bits = static_cast<uint8_t>(value);
  if (index >= kFirstDummy && index <= kLastDummy) {
    if (direction != PdoDirection::kReceive) {
      return AbortCode::kNotMappable;
    }
    return bits == dummyBytes(index) * 8U ? AbortCode::kNone : AbortCode::kParameterIncompatible;
  }
  od::EntryRef ref;
  const AbortCode found = dictionary.find(index, subIndex, &ref);
  if (found != AbortCode::kNone) {
    return found;
  }
  const uint16_t needed =
      direction == PdoDirection::kReceive ? od::kRpdoMappable : od::kTpdoMappable;
  if ((ref.attributes() & needed) == 0U) {
    return AbortCode::kNotMappable;
  }
  if (ref.size() == 0U || bits != ref.size() * 8U) {
    return AbortCode::kParameterIncompatible;
  }
  return AbortCode::kNone;
}

AbortCode PdoMap::resolve(const od::ObjectDictionary& dictionary, const uint32_t* values,
                          size_t count, PdoDirection direction) noexcept {
  clear();
  size_t bits = 0;
  for (size_t i = 0; i < count; ++i) {
    bits += values[i] & 0xFFU;
  }
  if (bits > kMaxBytes * 8U || count > kMaxEntries) {
    return AbortCode::kMappingTooLong;
  }
  Slot resolved[kMaxEntries] = {};
  size_t used = 0;
  size_t total = 0;
  for (size_t i = 0; i < count; ++i) {
    const AbortCode verdict = checkEntry(dictionary, values[i], direction);
    if (verdict != AbortCode::kNone) {
      return verdict;
    }
    if (values[i] == 0U) {
      continue;
    }
    const auto index = static_cast<uint16_t>(values[i] >> 16U);
    Slot& slot = resolved[used++];
    slot.bytes = static_cast<uint8_t>((values[i] & 0xFFU) / 8U);
    if (index < kFirstDummy || index > kLastDummy) {
      slot.ref = dictionary.find(index, static_cast<uint8_t>(values[i] >> 8U));
    }
    total += slot.bytes;
  }
  for (size_t i = 0; i < used; ++i) {
    slots_[i] = resolved[i];
  }
  count_ = used;
  bytes_ = total;
  return AbortCode::kNone;
}

bool PdoMap::contains(uint16_t index, uint8_t subIndex) const noexcept {
  for (size_t i = 0; i < count_; ++i) {
    const od::EntryRef& ref = slots_[i].ref;
    if (ref.valid() && ref.index() == index && ref.subIndex() == subIndex) {
      return true;
    }
  }
  return false;
}

void PdoMap::pack(const od::ObjectDictionary& dictionary, uint8_t* out) const noexcept {
  size_t offset = 0;
  for (size_t i = 0; i < count_; ++i) {
    const Slot& slot = slots_[i];
    for (size_t b = 0; b < slot.bytes; ++b) {
      out[offset + b] = 0;
    }
    if (slot.ref.valid()) {
      dictionary.read(slot.ref, 0, out + offset, slot.bytes);
    }
    offset += slot.bytes;
  }
}

AbortCode PdoMap::unpack(ObjectAccess& access, const uint8_t* data) const noexcept {
  size_t offset = 0;
  for (size_t i = 0; i < count_; ++i) {
    const Slot& slot = slots_[i];
    if (slot.ref.valid()) {
      const AbortCode verdict = access.dictionary().check(slot.ref, data + offset, slot.bytes);
      if (verdict != AbortCode::kNone) {
        return verdict;
      }
    }
    offset += slot.bytes;
  }
  offset = 0;
  AbortCode result = AbortCode::kNone;
  for (size_t i = 0; i < count_; ++i) {
    const Slot& slot = slots_[i];
    if (slot.ref.valid()) {
      const AbortCode written = access.write(slot.ref, data + offset, slot.bytes);
      if (written != AbortCode::kNone && result == AbortCode::kNone) {
        result = written;
      }
    }
    offset += slot.bytes;
  }
  return result;
}

}  // namespace costa
