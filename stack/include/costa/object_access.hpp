// Remote access to the dictionary on behalf of a client (SDO) or a PDO: access rights, hooks,
// then the dictionary's own checks.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/features.hpp"
#include "costa/hook_registry.hpp"
#include "costa/hot_path.hpp"
#include "costa/object_hook.hpp"
#include "costa/od/object_dictionary.hpp"
#include "costa/service_objects.hpp"

namespace costa {

/// Told of every successful remote write (SDO or RPDO), after the hook has run. The stack's one
/// observer is the save on write of parameter storage (ObjectAccess::setObserver()).
class WriteObserver {
 public:
  /// `changed` is false when the entry held the same bytes before. A code other than kNone
  /// reports that what the observer does with the value failed (a save on write: 0x08000020);
  /// the value stays written and the remote write answers with that code.
  virtual AbortCode onWritten(const od::EntryRef& ref, bool changed) noexcept {
    (void)ref;
    (void)changed;
    return AbortCode::kNone;
  }

 protected:
  WriteObserver() = default;
  ~WriteObserver() = default;
  WriteObserver(const WriteObserver&) = default;
  WriteObserver& operator=(const WriteObserver&) = default;
  WriteObserver(WriteObserver&&) = default;
  WriteObserver& operator=(WriteObserver&&) = default;
};

/// The way every remote access goes (SDO, PDO entries that need more than a copy): access
/// rights, the hook of the entry (the application's, else the owning service's, else the plain
/// dictionary), then the dictionary's checks. Context: the one that runs the node; no
/// allocation; every call O(log objects + application hooks) plus the hook's cost.
class ObjectAccess {
 public:
  ObjectAccess(od::ObjectDictionary& dictionary, const HookRegistry& hooks,
               const ServiceObjects& services) noexcept
      : dictionary_(dictionary), hooks_(hooks), services_(services) {}

  od::ObjectDictionary& dictionary() noexcept { return dictionary_; }
  const od::ObjectDictionary& dictionary() const noexcept { return dictionary_; }

  /// The hook behind `index`: an application hook, else the service that owns the object,
  /// else null (the plain dictionary).
  COSTA_SHARED_INLINE ObjectHook* hookOf(uint16_t index) const noexcept {
    ObjectHook* hook = hooks_.find(index);
    return hook != nullptr ? hook : services_.find(index);
  }

  /// Locates an entry for reading: kNoObject, kNoSubIndex, kReadOfWriteOnly, or the hook's
  /// refusal. On success the value may be read from the dictionary.
  AbortCode prepareRead(uint16_t index, uint8_t subIndex, const ReadRequest& request,
                        od::EntryRef* out) noexcept {
    const AbortCode found = dictionary_.find(index, subIndex, out);
    if (found != AbortCode::kNone) {
      return found;
    }
    if (!out->has(od::kReadable)) {
      return AbortCode::kReadOfWriteOnly;
    }
    ObjectHook* hook = hooks_.find(index);
    if (hook == nullptr) {
      hook =
          services_.findReader(index);  // of the stack's own services, only those that refine reads
    }
    return hook == nullptr ? AbortCode::kNone : hook->prepareRead(dictionary_, *out, request);
  }

  /// Locates an entry for writing: kNoObject, kNoSubIndex, kWriteOfReadOnly.
  AbortCode locateForWrite(uint16_t index, uint8_t subIndex, od::EntryRef* out) const noexcept {
    const AbortCode found = dictionary_.find(index, subIndex, out);
    if (found != AbortCode::kNone) {
      return found;
    }
    return out->has(od::kWritable) ? AbortCode::kNone : AbortCode::kWriteOfReadOnly;
  }

  /// Checks a value as a write of a located entry would, without writing (ObjectHook::check).
  AbortCode check(const od::EntryRef& ref, const uint8_t* data, size_t length) noexcept;
  /// Writes a located entry through its hook (or the plain dictionary).
  AbortCode write(const od::EntryRef& ref, const uint8_t* data, size_t length) noexcept;

  /// The streaming functions of the entry's hook (ObjectHook::readStream, writeStream,
  /// abortWriteStream), or their plain defaults when no hook covers the entry.
  AbortCode readStream(const od::EntryRef& ref, size_t offset, uint8_t* destination,
                       size_t capacity, size_t* produced, size_t* totalSize) noexcept;
  AbortCode writeStream(const od::EntryRef& ref, size_t offset, const uint8_t* source,
                        size_t length, bool last, size_t indicatedSize) noexcept;
  void abortWriteStream(const od::EntryRef& ref, AbortCode reason) noexcept;

  /// Tells `observer` (may be null) of every successful remote write. The one observer is the
  /// save on write of parameter storage: compiled out (features::kParameterStorage), writes
  /// are never observed, and the code that would tell an observer is left out of the image.
  void setObserver(WriteObserver* observer) noexcept { observer_ = observer; }
  bool observed() const noexcept { return features::kParameterStorage && observer_ != nullptr; }

 private:
  /// The behaviour of an entry no hook covers.
  class PlainHook final : public ObjectHook {};

  AbortCode writeObserved(const od::EntryRef& ref, const uint8_t* data, size_t length) noexcept;

  ObjectHook& hookFor(const od::EntryRef& ref) noexcept {
    ObjectHook* hook = hookOf(ref.index());
    if (hook == nullptr) {
      hook = &plain_;
    }
    return *hook;
  }

  od::ObjectDictionary& dictionary_;
  const HookRegistry& hooks_;
  const ServiceObjects& services_;
  WriteObserver* observer_ = nullptr;
  PlainHook plain_;
};

}  // namespace costa
