// An integer entry resolved once to where its value lives.
#pragma once

#include <stdint.h>

namespace costa::od {

class ObjectDictionary;

/// One sub-index resolved, by ObjectDictionary::scalar(), to where its value lies, its size and
/// its sign, for a caller that reads or stores the same entry every cycle: the dictionary's
/// readUnsigned() and storeUnsigned() of a Scalar do exactly what those of its EntryRef do
/// (0 and no store for an entry that is not an integer or boolean; no store into ROM; a
/// `$NODEID` constant read with the node-id), without decoding the entry again. Valid while the
/// dictionary's definition is; 8 bytes.
class Scalar {
 public:
  /// The dictionary has the entry.
  bool valid() const noexcept { return (flags_ & kPresent) != 0U; }

 private:
  friend class ObjectDictionary;
  static constexpr uint8_t kPresent = 0x01U;
  static constexpr uint8_t kSigned = 0x02U;      ///< sign-extended from `size_` bytes
  static constexpr uint8_t kInRom = 0x04U;       ///< among the constants: read-only
  static constexpr uint8_t kAddsNodeId = 0x08U;  ///< a `$NODEID` constant

  uint32_t offset_ = 0;  ///< in the RAM values, or in the constants with kInRom
  uint8_t size_ = 0;     ///< 0 for an entry that is not an integer or boolean: it reads as 0
  uint8_t flags_ = 0;
};

}  // namespace costa::od
