#include "storage_rules.hpp"

#include <vector>

#include "costa/cob_ids.hpp"
#include "costa/node.hpp"
#include "costa/parameter_store.hpp"
#include "costa/store_commands.hpp"
#include "dictionary_rules.hpp"

namespace costa::fuzz {
namespace {

/// Bit g set for every storage group g (1..31) that some entry of `definition` belongs to.
uint32_t groupsOf(const od::Definition& definition) {
  uint32_t groups = 0;
  for (size_t i = 0; i < definition.objectCount; ++i) {
    const od::Object& object = definition.objects[i];
    for (size_t r = 0; r < object.rowCount; ++r) {
      groups |= groupBit(od::rowsOf(definition, object)[r].group);
    }
  }
  return groups & ~groupBit(od::kGroupNone);
}

}  // namespace

std::string checkStoredParameters(const od::Definition& definition, uint8_t nodeId,
                                  NvStorage& storage) {
  // A RAM block for the copy, aligned for any scalar.
  std::vector<uint64_t> block((definition.valuesSize + sizeof(uint64_t) - 1U) / sizeof(uint64_t));
  od::ObjectDictionary dictionary(definition, block.data());
  dictionary.setNodeId(nodeId);
  dictionary.restoreDefaults(0x0000, 0xFFFF);
  ParameterStore store(dictionary, storage);
  if (!store.reserveRecord(Node::kLssRecord, Node::kLssRecordLength) || !store.layOut()) {
    return "stored parameters: the storage cannot hold the layout";
  }
  const uint32_t groups = groupsOf(definition);
  for (uint8_t group = 1; group < 32U; ++group) {
    if ((groups & groupBit(group)) == 0U) {
      continue;
    }
    const StoreResult result = store.load(group);
    if (result != StoreResult::kOk && result != StoreResult::kNoImage) {
      return "stored parameters: group " + std::to_string(group) + " loads as '" +
             toString(result) + "'";
    }
  }
  uint8_t record[Node::kLssRecordLength] = {};
  size_t length = 0;
  const StoreResult lss = store.loadRecord(Node::kLssRecord, record, sizeof(record), &length);
  if (lss != StoreResult::kOk && lss != StoreResult::kNoImage) {
    return std::string("stored parameters: LSS record loads as '") + toString(lss) + "'";
  }
  if (lss == StoreResult::kOk &&
      (length != sizeof(record) ||
       (!cob::isValidNodeId(record[0]) && record[0] != cob::kLssUnconfigured))) {
    return "stored parameters: LSS record of " + std::to_string(length) + " bytes, node-id " +
           std::to_string(record[0]);
  }
  const std::string values = checkDictionaryValues(dictionary);
  return values.empty() ? "" : "stored parameters: " + values;
}

}  // namespace costa::fuzz
