// One located sub-index of a dictionary, and the walk over every sub-index of a definition.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/od/definition.hpp"

namespace costa::od {

/// A located sub-index: its object, the row describing it, the sub-index itself and where its
/// value lies. Plain data, valid as long as the Definition it points into (ROM). Every accessor
/// is O(1). Made by at() (or a dictionary's find()), which computes the offset once.
struct EntryRef {
  const Object* object = nullptr;
  const SubEntry* row = nullptr;
  uint8_t sub = 0;
  uint16_t blockOffset = 0;  ///< offset(): computed by at()

  /// Sub-index `sub` of `row` (one of `object`'s rows, which holds it).
  static constexpr EntryRef at(const Object& object, const SubEntry& row, uint8_t sub) noexcept {
    return EntryRef{&object, &row, sub,
                    static_cast<uint16_t>(od::valueOffset(object, row, sub - row.subIndex))};
  }

  bool valid() const noexcept { return row != nullptr; }
  uint16_t index() const noexcept { return object->index; }
  uint8_t subIndex() const noexcept { return sub; }
  DataType type() const noexcept { return row->type; }
  uint8_t attributes() const noexcept { return row->attributes; }
  bool has(Attribute attribute) const noexcept { return (row->attributes & attribute) != 0U; }
  /// Bytes of the value (capacity of a VISIBLE_STRING, 0 for a DOMAIN).
  uint16_t size() const noexcept { return row->size; }
  uint8_t group() const noexcept { return row->group; }
  bool inRom() const noexcept { return has(kInRom); }
  /// Offset of the value in its block (the RAM values, or the ROM constants when inRom()).
  uint32_t offset() const noexcept { return blockOffset; }
};

/// Every sub-index of a definition, objects by index and sub-indices in order:
///   for (const EntryRef& ref : Entries(definition)) { ... }
/// No allocation; the whole walk is O(number of sub-indices).
class Entries {
 public:
  /// Where the walk ends: past the last sub-index.
  struct End {};

  class Iterator {
   public:
    Iterator(const Definition& definition, uint16_t object) noexcept
        : definition_(&definition), object_(object) {
      settle();
    }
    const EntryRef& operator*() const noexcept { return ref_; }
    const EntryRef* operator->() const noexcept { return &ref_; }
    Iterator& operator++() noexcept {
      ++step_;
      settle();
      return *this;
    }
    /// The walk goes on while the iterator locates a sub-index.
    bool operator!=(End /*end*/) const noexcept { return ref_.valid(); }

   private:
    /// Moves past rows and objects that are exhausted, then fills `ref_`.
    void settle() noexcept {
      while (object_ < definition_->objectCount) {
        const Object& object = definition_->objects[object_];
        if (row_ < object.rowCount) {
          const SubEntry& row = rowsOf(*definition_, object)[row_];
          if (step_ < row.count) {
            ref_ = EntryRef::at(object, row, static_cast<uint8_t>(row.subIndex + step_));
            return;
          }
          ++row_;
        } else {
          ++object_;
          row_ = 0;
        }
        step_ = 0;
      }
      ref_ = EntryRef{};
    }

    const Definition* definition_;
    uint16_t object_;
    uint8_t row_ = 0;
    unsigned step_ = 0;
    EntryRef ref_;
  };

  explicit Entries(const Definition& definition) noexcept : definition_(definition) {}
  Iterator begin() const noexcept { return {definition_, 0}; }
  static End end() noexcept { return {}; }

 private:
  const Definition& definition_;
};

/// The sub-index `sub` of `object` (one of `definition`'s); an invalid ref when the object has
/// none. O(rows).
inline EntryRef locate(const Definition& definition, const Object& object, uint8_t sub) noexcept {
  const SubEntry* rows = rowsOf(definition, object);
  for (uint8_t i = 0; i < object.rowCount; ++i) {
    const SubEntry& row = rows[i];
    if (sub >= row.subIndex && static_cast<unsigned>(sub - row.subIndex) < row.count) {
      return EntryRef::at(object, row, sub);
    }
  }
  return EntryRef{};
}

}  // namespace costa::od
