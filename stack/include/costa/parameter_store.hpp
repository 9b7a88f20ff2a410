// Saves and loads the dictionary's storage groups, and raw records, in non-volatile storage.
// Format and power-loss argument: docs/storage.md.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/od/object_dictionary.hpp"
#include "costa/port/nv_storage.hpp"
#include "costa/stored_image.hpp"

namespace costa {

/// Outcome of a ParameterStore operation.
enum class StoreResult : uint8_t {
  kOk,            ///< Done. After a load, the stored values are in place.
  kNoImage,       ///< Nothing stored, or a "restore defaults" marker: nothing was loaded.
  kCorrupt,       ///< Something was stored but no image is intact: nothing was loaded.
  kIncompatible,  ///< An intact image made for another layout (layoutId, region size, location
                  ///< or format version): nothing was loaded.
  kMediumError,   ///< The medium refused a read, write, erase or commit.
  kUnknownGroup,  ///< No entry of the dictionary is in this group, or the record is not reserved.
  kTooLong,       ///< Record data longer than its reservation, or than the caller's buffer.
  kNotLaidOut,    ///< layOut() has not succeeded since construction or the last reserveRecord().
};

/// Short name of a result ("ok", "no image", ...), for logs.
const char* toString(StoreResult result) noexcept;

/// Keeps each storage group of a dictionary (the entries whose SubEntry::group is not
/// od::kGroupNone) and each raw record the caller reserves in its own region of an NvStorage.
/// A region has two slots; a save writes the slot that does not hold the newest image and
/// commits, so a power loss at any moment leaves either the previous or the new image loadable.
///
/// Group payload: the RAM bytes of the group's entries in dictionary order (objects by index,
/// sub-entries by sub-index), SubEntry::size bytes each, in the CPU's byte order.
///
/// Writes happen only in save, invalidate, saveRecord and invalidateRecord. Loads check both
/// slots completely before they copy anything, so a damaged or foreign image never reaches the
/// dictionary or the caller's buffer. No allocation; a few hundred bytes of stack at most.
class ParameterStore {
 public:
  static constexpr size_t kMaxRegions = 12;  ///< Groups plus records.
  static constexpr size_t kMaxRecords = 4;

  /// `slotAlignment`: every slot starts at, and spans, a multiple of this many bytes (a flash
  /// page, so that erasing a slot never touches another); 0 and 1 mean none.
  ParameterStore(od::ObjectDictionary& dictionary, NvStorage& storage,
                 size_t slotAlignment = 1) noexcept;
  ParameterStore(const ParameterStore&) = delete;
  ParameterStore& operator=(const ParameterStore&) = delete;
  ~ParameterStore() = default;

  /// Reserves a region for up to `maxLength` bytes of raw data under `recordId` (data that is
  /// not in the dictionary, such as the LSS node-id and bit timing). Call before layOut(): a
  /// reservation undoes the layout. False when `recordId` is already reserved or kMaxRecords
  /// are.
  [[nodiscard]] bool reserveRecord(uint8_t recordId, size_t maxLength) noexcept;

  /// Bytes of storage the regions need: groups by ascending number, then records by ascending
  /// id, two slots each. SIZE_MAX when there would be more than kMaxRegions regions, or offsets
  /// beyond 32 bits.
  size_t requiredSize() const noexcept;
  /// Places the regions. False (and nothing usable) when the storage is smaller than
  /// requiredSize(). Reads and writes nothing.
  [[nodiscard]] bool layOut() noexcept;
  bool isLaidOut() const noexcept { return laidOut_; }

  /// True when some entry of the dictionary belongs to `group` (never for od::kGroupNone).
  bool hasGroup(uint8_t group) const noexcept;

  /// Stores the group's current values as the newest image.
  [[nodiscard]] StoreResult save(uint8_t group) noexcept;
  /// Copies the newest intact image of the group into the dictionary. Anything but kOk leaves
  /// the group's values as they were, except when the medium fails or changes during the copy
  /// (kMediumError, kCorrupt): then the group's defaults are restored rather than leave a mix.
  /// A copied value the dictionary refuses (outside its limits, a BOOLEAN above 1) gets its
  /// entry's default, and the load is still kOk: a firmware whose limits were wider may have
  /// stored it (the layout, layoutId, covers the stored entries and their types, not limits).
  [[nodiscard]] StoreResult load(uint8_t group) noexcept;
  /// Saves every group of `groups` (bit g for group g, see groupBit()) that the store holds,
  /// one after the other by ascending number, each on its own: a power loss in the middle
  /// leaves each group entirely old or entirely new (docs/storage.md, "Save all"). Stops at
  /// the first failure and returns it; kUnknownGroup when none of the groups is held.
  [[nodiscard]] StoreResult saveGroups(uint32_t groups) noexcept;
  /// invalidate() for every group of `groups` the store holds, in the same order and manner.
  [[nodiscard]] StoreResult invalidateGroups(uint32_t groups) noexcept;

  /// Stores a "restore defaults" marker as the newest image: the next load() yields kNoImage
  /// and leaves the defaults (CiA 301 0x1011: takes effect at the next reset). The dictionary
  /// is not changed.
  [[nodiscard]] StoreResult invalidate(uint8_t group) noexcept;

  /// Stores `length` bytes (at most the reserved length) as the newest image of the record.
  [[nodiscard]] StoreResult saveRecord(uint8_t recordId, const uint8_t* data,
                                       size_t length) noexcept;
  /// Copies the newest intact image of the record into `buffer` and sets `*length` (0 unless
  /// kOk). On anything but kOk the buffer is left as it was, except after a kMediumError or
  /// kCorrupt found while copying.
  [[nodiscard]] StoreResult loadRecord(uint8_t recordId, uint8_t* buffer, size_t capacity,
                                       size_t* length) noexcept;
  /// Stores a "no data" marker: the next loadRecord() yields kNoImage.
  [[nodiscard]] StoreResult invalidateRecord(uint8_t recordId) noexcept;

 private:
  struct Region {
    uint16_t id = 0;  ///< Group number, or kRecordRegion | record id.
    uint32_t layout = 0;
    size_t offset = 0;  ///< Of slot 0; slot 1 follows.
    size_t slotSize = 0;
    size_t payloadCapacity = 0;  ///< Exact payload length of a group; maximum of a record.
  };
  struct Record {
    uint8_t id;
    size_t maxLength;
  };
  /// Both slots of a region, which one holds the image that counts, and what it means.
  struct Examination {
    SlotInfo slots[2];
    size_t kept = 0;  ///< The slot whose image counts; the other one is written next.
    StoreResult verdict = StoreResult::kNoImage;
    uint32_t nextSequence = 1;
  };

  static constexpr uint16_t kRecordRegion = 0x0100U;
  static constexpr uint16_t recordRegion(uint8_t recordId) noexcept {
    return static_cast<uint16_t>(kRecordRegion | recordId);
  }

  /// Places the regions into `regions` (when not null); returns the bytes they span, or
  /// SIZE_MAX when they do not fit the limits.
  size_t computeLayout(Region* regions, size_t* count) const noexcept;
  size_t groupPayloadLength(uint8_t group) const noexcept;
  StoreResult findRegion(uint16_t id, const Region** region) const noexcept;
  size_t slotOffset(const Region& region, size_t slot) const noexcept {
    return region.offset + slot * region.slotSize;
  }
  bool isCurrent(const Region& region, size_t slot, const SlotInfo& info) const noexcept;
  int rank(const Region& region, size_t slot, const SlotInfo& info) const noexcept;
  bool examine(const Region& region, Examination* out) noexcept;
  StoreResult writeImage(const Region& region, ImageKind kind, const uint8_t* data,
                         size_t length) noexcept;

  od::ObjectDictionary& dictionary_;
  NvStorage& storage_;
  size_t slotAlignment_;
  Record records_[kMaxRecords] = {};
  size_t recordCount_ = 0;
  Region regions_[kMaxRegions] = {};
  size_t regionCount_ = 0;
  bool laidOut_ = false;
};

}  // namespace costa
