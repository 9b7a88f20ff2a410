// What a node's non-volatile storage holds can be loaded at any moment (docs/storage.md).
#pragma once

#include <stdint.h>

#include <string>

#include "costa/od/definition.hpp"
#include "costa/port/nv_storage.hpp"

namespace costa::fuzz {

/// Loads `storage` as a node with `definition` would after a power cycle, into a fresh copy of
/// the dictionary (defaults for node-id `nodeId`) through its own ParameterStore laid out like
/// the node's (every storage group, the LSS record of Node::kLssRecordLength bytes). Empty when
/// every group loads (kOk) or holds nothing to load (kNoImage), the LSS record likewise with a
/// node-id of 1..127 or 0xFF, and the loaded values pass checkDictionaryValues(); else what
/// failed. Reads the storage, never writes it.
std::string checkStoredParameters(const od::Definition& definition, uint8_t nodeId,
                                  NvStorage& storage);

}  // namespace costa::fuzz
