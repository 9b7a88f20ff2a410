// Behaviour behind dictionary entries: the way services and applications react to accesses.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/od/abort_code.hpp"
#include "costa/od/object_dictionary.hpp"

namespace costa {

/// Extra facts about a read request: the SDO initiate-upload frame's bytes 4..7, which CiA 301
/// reserves but some devices interpret (a channel selector, for example). All zero when the
/// read does not come from an expedited or segmented SDO upload (a block upload uses those
/// bytes for its block size and protocol switch threshold).
struct ReadRequest {
  uint8_t requestData[4] = {};
};

/// `indicatedSize` of ObjectHook::writeStream() when the client did not indicate the size.
inline constexpr size_t kSizeNotIndicated = SIZE_MAX;
/// The size a client indicated on the wire: itself, but never kSizeNotIndicated (a 32-bit
/// size_t would take 0xFFFFFFFF for it; one byte less is refused as too long all the same).
inline constexpr size_t indicatedSize(uint32_t wireSize) noexcept {
  const size_t size = wireSize;
  return size == kSizeNotIndicated ? size - 1U : size;
}

/// Attached to a range of indices with `Node::attachHook()`. The default implementation of each
/// function is the plain dictionary behaviour, so a hook overrides only what it changes.
///
/// Streamed entries: DOMAINs, and values larger than the SDO buffer, are not copied whole by
/// the SDO server; it moves them piecewise through readStream() and writeStream(), so that
/// their data may live with the hook (a file, a flash region, a log).
///
/// Hooks run in the context that runs the node (never in an interrupt), synchronously, while a
/// frame is handled; they must not block. They report failures as CiA 301 abort codes, which
/// the SDO server sends unchanged.
class ObjectHook {
 public:
  /// Called before a remote read takes the value: may refresh the value in RAM, or refuse.
  virtual AbortCode prepareRead(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                                const ReadRequest& request) noexcept {
    (void)dictionary;
    (void)ref;
    (void)request;
    return AbortCode::kNone;
  }

  /// Checks a value a remote write of `length` wire bytes would store, without storing it or
  /// acting: the first phase of an RPDO, which writes none of its entries unless every one
  /// passes. The default is the dictionary's check (length, BOOLEAN range, limits); a hook
  /// whose write() refuses more values should refuse them here too, so that an RPDO it refuses
  /// is refused before anything is written.
  virtual AbortCode check(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                          const uint8_t* data, size_t length) noexcept {
    return dictionary.check(ref, data, length);
  }

  /// Carries out a remote write of `length` wire bytes (access rights already checked). The
  /// default checks and stores the value; an override may validate further, transform, store
  /// elsewhere, or act after storing.
  virtual AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                          const uint8_t* data, size_t length) noexcept {
    return dictionary.write(ref, data, length);
  }

  /// Reads part of a streamed entry for a remote read (after prepareRead()): copies up to
  /// `capacity` bytes starting at byte `offset` to `destination`, sets `*produced` to the bytes
  /// copied and `*totalSize` to the size of the whole value. Fewer than `capacity` bytes are
  /// produced only at the end of the value. Any offset may be asked for, in any order (a block
  /// upload re-reads segments the client missed); `capacity` 0 asks for the size alone. The
  /// default reads the dictionary (an empty value for a DOMAIN).
  virtual AbortCode readStream(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                               size_t offset, uint8_t* destination, size_t capacity,
                               size_t* produced, size_t* totalSize) noexcept {
    *totalSize = dictionary.valueSize(ref);
    *produced = capacity == 0U ? 0U : dictionary.read(ref, offset, destination, capacity);
    return AbortCode::kNone;
  }

  /// Takes part of a remote write of a streamed entry (access rights already checked). Calls
  /// come in order with consecutive offsets: the first has offset 0 and, for segmented and block
  /// transfers, length 0 (it is made when the transfer starts, so that the hook can refuse, for
  /// example an `indicatedSize` it cannot hold, before data flows); `indicatedSize` is the size
  /// the client announced or kSizeNotIndicated. The call with `last` true completes the value
  /// (its length may be 0); a refusal there, as anywhere, aborts the transfer with that code.
  /// Every transfer that called writeStream() ends with either a successful `last` call or one
  /// abortWriteStream() call. The default refuses: kCannotStore for a DOMAIN, kOutOfMemory for
  /// a value too large for the SDO buffer.
  virtual AbortCode writeStream(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                                size_t offset, const uint8_t* source, size_t length, bool last,
                                size_t indicatedSize) noexcept {
    (void)dictionary;
    (void)offset;
    (void)source;
    (void)length;
    (void)last;
    (void)indicatedSize;
    return ref.type() == od::DataType::kDomain ? AbortCode::kCannotStore : AbortCode::kOutOfMemory;
  }

  /// A streamed write ends without a successful `last` call: the hook refused, the client or
  /// the server aborted (`reason` is the abort code: 0x05040004 for a CRC mismatch, 0x05040000
  /// for a timeout, the client's code for a client abort), or an NMT reset or stop dropped the
  /// transfer (kGeneral). The hook discards what it received.
  virtual void abortWriteStream(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                                AbortCode reason) noexcept {
    (void)dictionary;
    (void)ref;
    (void)reason;
  }

 protected:
  ObjectHook() = default;
  ~ObjectHook() = default;
  ObjectHook(const ObjectHook&) = default;
  ObjectHook& operator=(const ObjectHook&) = default;
  ObjectHook(ObjectHook&&) = default;
  ObjectHook& operator=(ObjectHook&&) = default;
};

}  // namespace costa
