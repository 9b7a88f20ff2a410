// The image stored in one slot of non-volatile storage: header format, writing and checking.
// Format and power-loss argument: docs/storage.md.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/crc32.hpp"
#include "costa/port/nv_storage.hpp"

namespace costa {

/// What an image holds.
enum class ImageKind : uint8_t {
  kValues = 0x01,    ///< A payload of stored values.
  kDefaults = 0x02,  ///< "Restore defaults" marker: no payload; loading yields the defaults.
};

/// Header fields of an image (all stored little-endian, see docs/storage.md).
struct ImageHeader {
  uint8_t formatVersion;
  ImageKind kind;
  uint16_t region;         ///< Which region the image belongs to (see ParameterStore).
  uint32_t layout;         ///< Definition::layoutId for dictionary groups, 0 for raw records.
  uint32_t location;       ///< Storage offset of the slot the image was written to.
  uint32_t payloadLength;  ///< Bytes of payload following the header.
  uint32_t sequence;       ///< Incremented per image written to the region (wraps).
  uint32_t crc;            ///< As stored; encodeImageHeader() does not use it.
};

inline constexpr uint8_t kImageFormatVersion = 2;  // 2: a moved $NODEID COB-ID is stored as it is
inline constexpr size_t kImageHeaderSize = 28;
inline constexpr size_t kImageMagicSize = 4;
inline constexpr uint8_t kImageMagic[kImageMagicSize] = {'C', 'S', 'T', 'P'};
/// Offset of the CRC in the header; the CRC covers the header bytes before it, then the payload.
inline constexpr size_t kImageCrcOffset = 24;

/// True when `a` was written after `b`, for sequences less than 2^31 apart (wrap-safe).
constexpr bool isNewerSequence(uint32_t a, uint32_t b) noexcept {
  return static_cast<int32_t>(a - b) > 0;
}

/// Header bytes 0..23 (magic through sequence), i.e. everything the CRC covers before the payload.
void encodeImageHeader(const ImageHeader& header, uint8_t* out) noexcept;

/// What a slot holds.
enum class SlotState : uint8_t {
  kBlank,       ///< No image: each magic byte is erased (0xFF) or right, not all are right
                ///< (never written, or a write or erase that did not finish).
  kDamaged,     ///< Not blank, but no intact image: foreign bytes, a bad CRC, an impossible length.
  kIntact,      ///< Magic complete and CRC correct; `header` is valid.
  kUnreadable,  ///< The medium refused a read.
};

struct SlotInfo {
  SlotState state = SlotState::kBlank;
  ImageHeader header{};
};

/// Reads and checks the slot of `slotSize` bytes at `offset`: header, then the CRC over header
/// and payload, streamed in small chunks. Never writes.
SlotInfo inspectSlot(NvStorage& storage, size_t offset, size_t slotSize) noexcept;

/// Writes one image into a slot. Usage: begin(), append() the payload in any pieces, finish().
/// The slot is erased first; the payload goes in through a small staging buffer while the CRC is
/// computed; then the header after the magic, then the magic, then commit. Until the magic is
/// complete the slot reads as kBlank, so an interrupted write never yields an image. Any medium
/// failure makes the remaining calls fail.
class ImageWriter {
 public:
  ImageWriter(NvStorage& storage, size_t slotOffset, size_t slotSize) noexcept
      : storage_(storage), slotOffset_(slotOffset), slotSize_(slotSize) {}

  /// Erases the slot. `header.payloadLength` must be exactly what append() will pass.
  bool begin(const ImageHeader& header) noexcept;
  bool append(const uint8_t* data, size_t length) noexcept;
  /// Flushes the payload, writes the header and the magic, commits. When the commit fails the
  /// slot is erased again (not committed): the failed save leaves the previous image kept.
  bool finish() noexcept;

 private:
  static constexpr size_t kStageSize = 32;
  bool flush() noexcept;

  NvStorage& storage_;
  size_t slotOffset_;
  size_t slotSize_;
  uint8_t header_[kImageHeaderSize] = {};
  uint8_t stage_[kStageSize] = {};
  size_t staged_ = 0;
  size_t written_ = 0;  ///< Payload bytes already written to the medium.
  size_t expected_ = 0;
  Crc32 crc_;
  bool ok_ = false;
};

/// Reads the payload of a slot that inspectSlot() found intact, recomputing the CRC, so that a
/// medium that changed since the check is noticed.
class ImageReader {
 public:
  ImageReader(NvStorage& storage, size_t slotOffset, const ImageHeader& header) noexcept;

  /// Copies the next `length` payload bytes to `destination`.
  bool read(uint8_t* destination, size_t length) noexcept;
  /// True when the whole payload was read and its CRC still matches.
  bool matches() const noexcept;

 private:
  NvStorage& storage_;
  size_t payloadOffset_;
  size_t payloadLength_;
  size_t position_ = 0;
  uint32_t expectedCrc_ = 0;
  Crc32 crc_;
  bool ok_ = true;
};

}  // namespace costa
