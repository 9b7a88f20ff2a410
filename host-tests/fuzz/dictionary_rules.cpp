#include "dictionary_rules.hpp"

#include <stdio.h>
#include <string.h>

#include <map>
#include <vector>

#include "costa/od/little_endian.hpp"

namespace costa::fuzz {
namespace {

double asDouble(od::DataType type, uint64_t raw) {
  if (type == od::DataType::kReal32) {
    float value = 0.0F;
    const auto bits = static_cast<uint32_t>(raw);
    memcpy(&value, &bits, sizeof(value));
    return static_cast<double>(value);
  }
  double value = 0.0;
  memcpy(&value, &raw, sizeof(value));
  return value;
}

/// The value of a numeric entry in RAM (CPU byte order), zero-extended. False for a size
/// that is not 1, 2, 4 or 8.
bool nativeValue(const uint8_t* address, size_t size, uint64_t* raw) {
  switch (size) {
    case 1: *raw = *address; return true;
    case 2: {
      uint16_t value = 0;
      memcpy(&value, address, sizeof(value));
      *raw = value;
      return true;
    }
    case 4: {
      uint32_t value = 0;
      memcpy(&value, address, sizeof(value));
      *raw = value;
      return true;
    }
    case 8: memcpy(raw, address, sizeof(*raw)); return true;
    default: return false;
  }
}

/// True when `raw` (the value's bits, zero-extended) is within the entry's limits; else false
/// with the value and the limits in `problem`.
bool withinLimits(const od::Definition& definition, const od::EntryRef& ref, uint64_t raw,
                  std::string* problem) {
  const od::Limits& limits = definition.limits[ref.row->limits - 1U];
  const od::DataType type = ref.type();
  char text[160];
  if (od::isSigned(type)) {
    const int64_t value = signExtend(raw, ref.size());
    const auto low = static_cast<int64_t>(limits.low);
    const auto high = static_cast<int64_t>(limits.high);
    if (value >= low && value <= high) {
      return true;
    }
    snprintf(text, sizeof(text), "%lld outside %lld..%lld", static_cast<long long>(value),
             static_cast<long long>(low), static_cast<long long>(high));
  } else if (od::isReal(type)) {
    const double value = asDouble(type, raw);
    const double low = asDouble(od::DataType::kReal64, limits.low);
    const double high = asDouble(od::DataType::kReal64, limits.high);
    if (value >= low && value <= high) {  // false for NaN
      return true;
    }
    snprintf(text, sizeof(text), "%g outside %g..%g", value, low, high);
  } else {
    if (raw >= limits.low && raw <= limits.high) {
      return true;
    }
    snprintf(text, sizeof(text), "%llu outside %llu..%llu", static_cast<unsigned long long>(raw),
             static_cast<unsigned long long>(limits.low),
             static_cast<unsigned long long>(limits.high));
  }
  *problem = text;
  return false;
}

/// True when the value of a RAM entry, at `address`, fits its definition; else false with the
/// reason in `problem`. (The value is read in place: the checks call none of the stack's code,
/// which the fuzzer instruments.)
bool entryFits(const od::Definition& definition, const od::EntryRef& ref, const uint8_t* address,
               std::string* problem) {
  const od::DataType type = ref.type();
  if (type == od::DataType::kVisibleString) {
    if (address[ref.size()] != 0U) {
      *problem = "string without its terminating zero";
      return false;
    }
    return true;
  }
  if (!od::isNumeric(type)) {
    return true;
  }
  uint64_t raw = 0;
  if (!nativeValue(address, ref.size(), &raw)) {
    *problem = "numeric value of " + std::to_string(ref.size()) + " bytes";
    return false;
  }
  if (type == od::DataType::kBoolean && raw > 1U) {
    *problem = "BOOLEAN " + std::to_string(raw);
    return false;
  }
  return ref.row->limits == 0U || withinLimits(definition, ref, raw, problem);
}

/// A RAM entry whose value can break a rule, and where its value is in the RAM block.
struct Constrained {
  od::EntryRef ref;
  uint32_t offset;
};

/// The entries whose value can break a rule (strings, BOOLEANs, entries with limits, numbers of
/// an odd size); the others accept every bit pattern. Worked out once per definition.
const std::vector<Constrained>& constrainedEntries(const od::Definition& definition) {
  static std::map<const od::Definition*, std::vector<Constrained>> known;
  const auto found = known.find(&definition);
  if (found != known.end()) {
    return found->second;
  }
  std::vector<Constrained>& entries = known[&definition];
  for (const od::EntryRef& ref : od::Entries(definition)) {
    const od::DataType type = ref.type();
    if (ref.inRom() || type == od::DataType::kDomain) {
      continue;
    }
    const bool oddSize =
        ref.size() != 1U && ref.size() != 2U && ref.size() != 4U && ref.size() != 8U;
    if (type == od::DataType::kVisibleString || type == od::DataType::kBoolean ||
        (od::isNumeric(type) && (ref.row->limits != 0U || oddSize))) {
      entries.push_back(Constrained{ref, ref.offset()});
    }
  }
  return entries;
}

}  // namespace

std::string checkDictionaryValues(const od::ObjectDictionary& dictionary) {
  const od::Definition& definition = dictionary.definition();
  const auto* values = static_cast<const uint8_t*>(dictionary.values());
  for (const auto& [ref, offset] : constrainedEntries(definition)) {
    std::string problem;
    if (!entryFits(definition, ref, values + offset, &problem)) {
      char where[32];
      snprintf(where, sizeof(where), "0x%04X:%02X: ", ref.index(),
               static_cast<unsigned>(ref.subIndex()));
      return std::string("dictionary value ") + where + problem;
    }
  }
  return "";
}

}  // namespace costa::fuzz
