// A dictionary with its own RAM block at its defaults, and helpers that read or fill the bytes
// of a storage group, for tests of stored parameters.
#pragma once

#include <stdint.h>

#include <vector>

#include "costa/od/object_dictionary.hpp"

namespace costa::test {

/// One dictionary instance as a node would hold it after a reset: defaults, node-id set.
template <typename Values>
struct DictionaryInstance {
  explicit DictionaryInstance(const od::Definition& definition, uint8_t nodeId = 1)
      : dictionary(definition, &values) {
    dictionary.setNodeId(nodeId);
    dictionary.restoreDefaults(0x0000, 0xFFFF);
  }
  Values values{};
  od::ObjectDictionary dictionary;
};

/// The RAM bytes of every entry of `group`, in dictionary order: what a stored image holds.
inline std::vector<uint8_t> groupBytes(od::ObjectDictionary& dictionary, uint8_t group) {
  std::vector<uint8_t> bytes;
  for (const od::EntryRef& ref : od::Entries(dictionary.definition())) {
    const uint8_t* address = dictionary.ramAddress(ref);
    if (ref.group() == group && address != nullptr) {
      bytes.insert(bytes.end(), address, address + ref.size());
    }
  }
  return bytes;
}

/// Fills every RAM byte of `group` with a pattern: byte j becomes seed * 31 + j * 7 + 1, so the
/// patterns of two seeds that differ by less than 256 differ in every byte, except in an entry
/// whose pattern the dictionary refuses (outside its limits, a BOOLEAN above 1): that one keeps
/// its default, as a load would give it.
inline void fillGroup(od::ObjectDictionary& dictionary, uint8_t group, unsigned seed) {
  size_t j = 0;
  for (const od::EntryRef& ref : od::Entries(dictionary.definition())) {
    uint8_t* address = dictionary.ramAddress(ref);
    if (ref.group() != group || address == nullptr) {
      continue;
    }
    for (size_t k = 0; k < ref.size(); ++k, ++j) {
      address[k] = static_cast<uint8_t>(seed * 31U + j * 7U + 1U);
    }
    (void)dictionary.restoreDefaultIfRefused(ref);
  }
}

}  // namespace costa::test
