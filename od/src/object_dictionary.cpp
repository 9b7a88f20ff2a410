#include "costa/od/object_dictionary.hpp"

#include <string.h>

#include "costa/od/little_endian.hpp"

namespace costa::od {
namespace {

// Native bytes of a numeric value, zero-extended to 64 bits (works on any byte order).
uint64_t loadNative(const uint8_t* address, size_t size) noexcept {
  switch (size) {
    case 1: return *address;
    case 2: {
      uint16_t v = 0;
      memcpy(&v, address, 2);
      return v;
    }
    case 4: {
      uint32_t v = 0;
      memcpy(&v, address, 4);
      return v;
    }
    case 8: {
      uint64_t v = 0;
      memcpy(&v, address, 8);
      return v;
    }
    default: return 0;
  }
}

void storeNative(uint8_t* address, uint64_t raw, size_t size) noexcept {
  switch (size) {
    case 1: *address = static_cast<uint8_t>(raw); break;
    case 2: {
      const auto v = static_cast<uint16_t>(raw);
      memcpy(address, &v, 2);
      break;
    }
    case 4: {
      const auto v = static_cast<uint32_t>(raw);
      memcpy(address, &v, 4);
      break;
    }
    case 8: memcpy(address, &raw, 8); break;
    default: break;
  }
}

double toDouble(DataType type, uint64_t raw) noexcept {
  if (type == DataType::kReal32) {
    float f = 0.0F;
    const auto bits = static_cast<uint32_t>(raw);
    memcpy(&f, &bits, 4);
    return static_cast<double>(f);
  }
  double d = 0.0;
  memcpy(&d, &raw, 8);
  return d;
}

// Compares a candidate numeric value (raw wire bits) with the entry's limits.
AbortCode checkLimits(const SubEntry& entry, uint64_t raw) noexcept {
  const Limits& limits = *entry.limits;
  if (isSigned(entry.type)) {
    const int64_t value = signExtend(raw, entry.size);
    if (value > static_cast<int64_t>(limits.high)) {
      return AbortCode::kValueTooHigh;
    }
    if (value < static_cast<int64_t>(limits.low)) {
      return AbortCode::kValueTooLow;
    }
  } else if (isReal(entry.type)) {
    const double value = toDouble(entry.type, raw);
    const double low = toDouble(DataType::kReal64, limits.low);
    const double high = toDouble(DataType::kReal64, limits.high);
    if (value != value) {  // NaN is in no range
      return AbortCode::kInvalidValue;
    }
    if (value > high) {
      return AbortCode::kValueTooHigh;
    }
    if (value < low) {
      return AbortCode::kValueTooLow;
    }
  } else {
    if (raw > limits.high) {
      return AbortCode::kValueTooHigh;
    }
    if (raw < limits.low) {
      return AbortCode::kValueTooLow;
    }
  }
  return AbortCode::kNone;
}

}  // namespace

ObjectDictionary::ObjectDictionary(const Definition& definition, void* values) noexcept
    : definition_(&definition), values_(static_cast<uint8_t*>(values)) {}

const Object* ObjectDictionary::findObject(uint16_t index) const noexcept {
  size_t low = 0;
  size_t high = definition_->objectCount;
  while (low < high) {
    const size_t middle = low + (high - low) / 2U;
    const Object& candidate = definition_->objects[middle];
    if (candidate.index == index) {
      return &candidate;
    }
    if (candidate.index < index) {
      low = middle + 1U;
    } else {
      high = middle;
    }
  }
  return nullptr;
}

AbortCode ObjectDictionary::find(uint16_t index, uint8_t subIndex, EntryRef* out) const noexcept {
  const Object* object = findObject(index);
  if (object == nullptr) {
    return AbortCode::kNoObject;
  }
  size_t low = 0;
  size_t high = object->subCount;
  while (low < high) {
    const size_t middle = low + (high - low) / 2U;
    const SubEntry& candidate = object->subs[middle];
    if (candidate.subIndex == subIndex) {
      out->object = object;
      out->entry = &candidate;
      return AbortCode::kNone;
    }
    if (candidate.subIndex < subIndex) {
      low = middle + 1U;
    } else {
      high = middle;
    }
  }
  return AbortCode::kNoSubIndex;
}

EntryRef ObjectDictionary::find(uint16_t index, uint8_t subIndex) const noexcept {
  EntryRef ref;
  if (find(index, subIndex, &ref) != AbortCode::kNone) {
    return EntryRef{};
  }
  return ref;
}

const uint8_t* ObjectDictionary::address(const SubEntry& entry) const noexcept {
  if (entry.type == DataType::kDomain) {
    return nullptr;
  }
  if ((entry.attributes & kInRom) != 0U) {
    return static_cast<const uint8_t*>(definition_->constants) + entry.offset;
  }
  return values_ + entry.offset;
}

uint8_t* ObjectDictionary::ramAddress(const SubEntry& entry) noexcept {
  if (entry.type == DataType::kDomain || (entry.attributes & kInRom) != 0U) {
    return nullptr;
  }
  return values_ + entry.offset;
}

size_t ObjectDictionary::valueSize(const SubEntry& entry) const noexcept {
  if (entry.type == DataType::kDomain) {
    return 0;
  }
  if (entry.type == DataType::kVisibleString) {
    const uint8_t* text = address(entry);
    size_t length = 0;
    while (length < entry.size && text[length] != 0U) {
      ++length;
    }
    return length;
  }
  return entry.size;
}

size_t ObjectDictionary::read(const SubEntry& entry, size_t offset, uint8_t* destination,
                              size_t capacity) const noexcept {
  const size_t total = valueSize(entry);
  if (offset >= total) {
    return 0;
  }
  size_t count = total - offset;
  if (count > capacity) {
    count = capacity;
  }
  if (isNumeric(entry.type)) {
    uint8_t wire[8];
    uint64_t raw = loadNative(address(entry), entry.size);
    if ((entry.attributes & (kNodeIdRelative | kInRom)) == (kNodeIdRelative | kInRom)) {
      raw += nodeId_;
    }
    storeLittleEndian(wire, raw, entry.size);
    memcpy(destination, wire + offset, count);
  } else {
    memcpy(destination, address(entry) + offset, count);
  }
  return count;
}

AbortCode ObjectDictionary::check(const SubEntry& entry, const uint8_t* source,
                                  size_t length) const noexcept {
  if ((entry.attributes & kInRom) != 0U) {
    return AbortCode::kWriteOfReadOnly;
  }
  if (entry.type == DataType::kDomain) {
    return AbortCode::kCannotStore;
  }
  if (entry.type == DataType::kVisibleString) {
    return length > entry.size ? AbortCode::kLengthTooHigh : AbortCode::kNone;
  }
  if (length > entry.size) {
    return AbortCode::kLengthTooHigh;
  }
  if (length < entry.size) {
    return AbortCode::kLengthTooLow;
  }
  if (!isNumeric(entry.type)) {
    return AbortCode::kNone;
  }
  const uint64_t raw = loadLittleEndian(source, entry.size);
  if (entry.type == DataType::kBoolean && raw > 1U) {
    return AbortCode::kInvalidValue;
  }
  if ((entry.attributes & kHasLimits) != 0U) {
    return checkLimits(entry, raw);
  }
  return AbortCode::kNone;
}

AbortCode ObjectDictionary::write(const SubEntry& entry, const uint8_t* source,
                                  size_t length) noexcept {
  const AbortCode verdict = check(entry, source, length);
  if (verdict != AbortCode::kNone) {
    return verdict;
  }
  uint8_t* target = values_ + entry.offset;
  if (isNumeric(entry.type)) {
    storeNative(target, loadLittleEndian(source, entry.size), entry.size);
  } else {
    memcpy(target, source, length);
    if (length < entry.size) {
      memset(target + length, 0, entry.size - length);
    }
  }
  return AbortCode::kNone;
}

uint64_t ObjectDictionary::readUnsigned(const SubEntry& entry) const noexcept {
  if (!isSigned(entry.type) && !isUnsigned(entry.type)) {
    return 0;
  }
  uint64_t raw = loadNative(address(entry), entry.size);
  if ((entry.attributes & (kNodeIdRelative | kInRom)) == (kNodeIdRelative | kInRom)) {
    raw += nodeId_;
  }
  if (isSigned(entry.type)) {
    return static_cast<uint64_t>(signExtend(raw, entry.size));
  }
  return raw;
}

int64_t ObjectDictionary::readSigned(const SubEntry& entry) const noexcept {
  return static_cast<int64_t>(readUnsigned(entry));
}

void ObjectDictionary::storeUnsigned(const SubEntry& entry, uint64_t value) noexcept {
  uint8_t* target = ramAddress(entry);
  if (target == nullptr || !(isSigned(entry.type) || isUnsigned(entry.type))) {
    return;
  }
  storeNative(target, value, entry.size);
}

uint64_t ObjectDictionary::readUnsigned(uint16_t index, uint8_t subIndex,
                                        uint64_t fallback) const noexcept {
  const EntryRef ref = find(index, subIndex);
  return ref.valid() ? readUnsigned(*ref.entry) : fallback;
}

bool ObjectDictionary::storeUnsigned(uint16_t index, uint8_t subIndex, uint64_t value) noexcept {
  const EntryRef ref = find(index, subIndex);
  if (!ref.valid()) {
    return false;
  }
  storeUnsigned(*ref.entry, value);
  return true;
}

void ObjectDictionary::restoreEntry(const SubEntry& entry) noexcept {
  uint8_t* target = ramAddress(entry);
  if (target == nullptr) {
    return;
  }
  const size_t bytes = entry.type == DataType::kVisibleString ? entry.size + 1U : entry.size;
  memcpy(target, static_cast<const uint8_t*>(definition_->defaults) + entry.offset, bytes);
  if ((entry.attributes & kNodeIdRelative) != 0U) {
    storeNative(target, loadNative(target, entry.size) + nodeId_, entry.size);
  }
}

void ObjectDictionary::restoreDefaults(uint16_t first, uint16_t last) noexcept {
  for (size_t i = 0; i < definition_->objectCount; ++i) {
    const Object& object = definition_->objects[i];
    if (object.index < first || object.index > last) {
      continue;
    }
    for (size_t s = 0; s < object.subCount; ++s) {
      restoreEntry(object.subs[s]);
    }
  }
}

void ObjectDictionary::restoreGroupDefaults(uint8_t group) noexcept {
  for (size_t i = 0; i < definition_->objectCount; ++i) {
    const Object& object = definition_->objects[i];
    for (size_t s = 0; s < object.subCount; ++s) {
      if (object.subs[s].group == group) {
        restoreEntry(object.subs[s]);
      }
    }
  }
}

}  // namespace costa::od
