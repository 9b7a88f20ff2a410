// What the dictionary and CAN-ID rules of the fuzz session depend on, as it was at the last
// checks that passed: while it is unchanged, so are their verdicts, and the session does not
// work them out again after every event.
#pragma once

#include <stdint.h>
#include <string.h>

#include <vector>

#include "costa/node.hpp"
#include "frame_rules.hpp"

namespace costa::fuzz {

/// The dictionary's RAM values, the node-id and the NMT state when the dictionary rules
/// (dictionary_rules.hpp) and the CAN-ID rules (frame_rules.hpp) last passed, and the CAN-IDs
/// the node could use then. Those rules read nothing else of a node that could change: its
/// definition, its constants and its profile are the same for every input of a device.
class CheckedState {
 public:
  /// True when `node` has the values, node-id and NMT state remembered last.
  bool same(const Node& node) const {
    const od::ObjectDictionary& dictionary = node.dictionary();
    return valid_ && node.nodeId() == nodeId_ && node.state() == state_ &&
           dictionary.definition().valuesSize == values_.size() &&
           memcmp(dictionary.values(), values_.data(), values_.size()) == 0;
  }

  /// Remembers `node` as it is, with the CAN-IDs it may use (allowedTransmitIds()).
  void remember(const Node& node, const CanIdSet& allowed) {
    const od::ObjectDictionary& dictionary = node.dictionary();
    const auto* values = static_cast<const uint8_t*>(dictionary.values());
    values_.assign(values, values + dictionary.definition().valuesSize);
    nodeId_ = node.nodeId();
    state_ = node.state();
    allowed_ = allowed;
    valid_ = true;
  }

  /// The CAN-IDs remembered with the node.
  const CanIdSet& allowed() const { return allowed_; }

 private:
  std::vector<uint8_t> values_;
  uint8_t nodeId_ = 0;
  NmtState state_ = NmtState::kInitialising;
  CanIdSet allowed_;
  bool valid_ = false;
};

}  // namespace costa::fuzz
