#include "costa/pdo_map.hpp"

#include "costa/od/bytes.hpp"
#include "costa/od/little_endian.hpp"

namespace costa {
namespace {

constexpr uint16_t kFirstDummy = 0x0002;  // INTEGER8
constexpr uint16_t kLastDummy = 0x0007;   // UNSIGNED32

// The length in bytes of dummy entry `index` (INTEGER8..INTEGER32, UNSIGNED8..UNSIGNED32): 1, 2,
// 4, 1, 2, 4, one nibble each from the lowest.
uint32_t dummyBytes(uint16_t index) noexcept {
  return (0x421421U >> ((index - kFirstDummy) * 4U)) & 0xFU;
}

bool isDummy(uint16_t index) noexcept {
  return index >= kFirstDummy && index <= kLastDummy;
}

}  // namespace

AbortCode PdoMap::checkEntry(const od::ObjectDictionary& dictionary, uint32_t value,
                             PdoDirection direction, od::EntryRef* ref) noexcept {
  if (value == 0U) {
    return AbortCode::kNone;
  }
  const auto index = static_cast<uint16_t>(value >> 16U);
  const auto bits = static_cast<uint8_t>(value);
  if (isDummy(index)) {  // a gap in an RPDO, where the dictionary's [DummyUsage] allows it
    if (direction != PdoDirection::kReceive ||
        (dictionary.definition().dummyUsage & (1U << index)) == 0U) {
      return AbortCode::kNotMappable;
    }
    return bits == dummyBytes(index) * 8U ? AbortCode::kNone : AbortCode::kParameterIncompatible;
  }
  const AbortCode found = dictionary.find(index, static_cast<uint8_t>(value >> 8U), ref);
  if (found != AbortCode::kNone) {
    return found;
  }
  const od::Attribute needed =
      direction == PdoDirection::kReceive ? od::kRpdoMappable : od::kTpdoMappable;
  if (!ref->has(needed)) {
    return AbortCode::kNotMappable;
  }
  if (ref->size() == 0U || bits != ref->size() * 8U) {
    return AbortCode::kParameterIncompatible;
  }
  return AbortCode::kNone;
}

AbortCode PdoMap::resolve(const ObjectAccess& access, const uint32_t* values, size_t count,
                          PdoDirection direction) noexcept {
  clear();
  size_t bits = 0;
  for (size_t i = 0; i < count; ++i) {
    bits += values[i] & 0xFFU;
  }
  if (bits > kMaxBytes * 8U || count > kMaxEntries) {
    return AbortCode::kMappingTooLong;
  }
  const od::ObjectDictionary& dictionary = access.dictionary();
  for (size_t i = 0; i < count; ++i) {
    od::EntryRef ref;
    const AbortCode verdict = checkEntry(dictionary, values[i], direction, &ref);
    if (verdict != AbortCode::kNone) {
      clear();  // refused: empty, as before the first entry
      return verdict;
    }
    if (values[i] == 0U) {
      continue;
    }
    const size_t slot = count_++;
    const auto bit = static_cast<uint8_t>(1U << slot);
    Slot& entry = slots_[slot];
    entry.length = static_cast<uint8_t>((values[i] & 0xFFU) / 8U);
    bytes_ = static_cast<uint8_t>(bytes_ + entry.length);
    if (!ref.valid()) {  // a dummy entry
      markMask_ |= bit;
      continue;
    }
    const uint16_t index = ref.index();
    // A TPDO copies constants too, unless the node-id is added to them when read.
    const bool constant =
        ref.inRom() && direction == PdoDirection::kTransmit && !ref.has(od::kNodeIdRelative);
    bool copied = (!ref.inRom() || constant) && (kLittleEndianHost || entry.length == 1U);
    if (direction == PdoDirection::kReceive) {
      copied = copied && access.hookOf(index) == nullptr && ref.row->limits == 0U &&
               ref.type() != od::DataType::kBoolean &&
               !(access.observed() && ref.group() != od::kGroupNone);
    }
    if (copied) {
      entry.where = static_cast<uint16_t>(ref.offset());
      if (constant) {
        markMask_ |= bit;
      }
    } else {
      entry.where = index;
      entry.subIndex = ref.subIndex();
      accessMask_ |= bit;
    }
  }
  return AbortCode::kNone;
}

bool PdoMap::contains(const od::EntryRef& ref) const noexcept {
  // A TPDO's map (the only one asked): no dummy entries; inRom() tells the two value blocks apart,
  // and within a block an offset is one entry's (the generator shares a constant's place between
  // objects only when no PDO may map it). A DOMAIN is never mapped (it has no size), and its
  // offset is no value's.
  if (ref.type() == od::DataType::kDomain) {
    return false;
  }
  for (size_t i = 0; i < count_; ++i) {
    const Slot& slot = slots_[i];
    const bool same = needsAccess(i) ? slot.where == ref.index() && slot.subIndex == ref.subIndex()
                                     : ref.inRom() == inRom(i) && slot.where == ref.offset();
    if (same) {
      return true;
    }
  }
  return false;
}

void PdoMap::packThroughAccess(const ObjectAccess& access, uint8_t* out) const noexcept {
  const od::ObjectDictionary& dictionary = access.dictionary();
  const auto* values = static_cast<const uint8_t*>(dictionary.values());
  const auto* constants = static_cast<const uint8_t*>(dictionary.definition().constants);
  for (size_t i = 0; i < count_; ++i) {
    const Slot& slot = slots_[i];
    if (!needsAccess(i)) {
      copyValue(out, (inRom(i) ? constants : values) + slot.where, slot.length);
    } else {
      fillBytes(out, 0, slot.length);
      dictionary.read(locate(access, i), 0, out, slot.length);
    }
    out += slot.length;
  }
}

AbortCode PdoMap::writeThroughAccess(ObjectAccess& access, const uint8_t* data) const noexcept {
  auto* values = static_cast<uint8_t*>(access.dictionary().values());
  // Where each entry was written (nullptr: not in RAM, or a dummy entry) and what it held before,
  // at most kMaxBytes bytes in all; with no entry that can refuse (no bit in accessMask_),
  // nothing is saved, as nothing is put back.
  const bool refusable = accessMask_ != 0U;
  uint8_t before[kMaxBytes];
  uint8_t* saved[kMaxEntries];
  size_t offset = 0;
  for (size_t i = 0; i < count_; offset += slots_[i].length, ++i) {
    const Slot& slot = slots_[i];
    saved[i] = nullptr;
    if (skipped(i)) {
      continue;
    }
    AbortCode written = AbortCode::kNone;
    if (needsAccess(i)) {
      const od::EntryRef ref = locate(access, i);
      saved[i] = access.dictionary().ramAddress(ref);
      if (saved[i] != nullptr) {
        copyValue(before + offset, saved[i], slot.length);
      }
      written = access.write(ref, data + offset, slot.length);
    } else {
      saved[i] = values + slot.where;
      if (refusable) {
        copyValue(before + offset, saved[i], slot.length);
      }
      copyValue(saved[i], data + offset, slot.length);
    }
    if (written != AbortCode::kNone) {
      // Everything goes back, the refusing entry too (its hook may have changed it first), the
      // last written first: an entry mapped twice gets the bytes it held before the PDO.
      for (size_t j = i + 1U, back = offset + slot.length; j-- > 0U;) {
        back -= slots_[j].length;
        if (saved[j] != nullptr) {
          copyValue(saved[j], before + back, slots_[j].length);
        }
      }
      return written;
    }
  }
  return AbortCode::kNone;
}

}  // namespace costa
