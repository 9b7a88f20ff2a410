#include "costa/object_access.hpp"

#include "costa/od/bytes.hpp"

namespace costa {

AbortCode ObjectAccess::check(const od::EntryRef& ref, const uint8_t* data,
                              size_t length) noexcept {
  return hookFor(ref).check(dictionary_, ref, data, length);
}

// Out of line: it has many callers, and expanded into each it costs flash (200 bytes on
// Cortex-M0+) and, in the expedited download, instructions too.
AbortCode ObjectAccess::write(const od::EntryRef& ref, const uint8_t* data,
                              size_t length) noexcept {
  if constexpr (features::kParameterStorage) {
    if (observer_ != nullptr) {
      return writeObserved(ref, data, length);
    }
  }
  ObjectHook* hook = hookOf(ref.index());
  return hook != nullptr ? hook->write(dictionary_, ref, data, length)
                         : dictionary_.write(ref, data, length);
}

AbortCode ObjectAccess::writeObserved(const od::EntryRef& ref, const uint8_t* data,
                                      size_t length) noexcept {
  // Small values are compared before and after, so that the observer can skip unchanged ones.
  uint8_t before[8] = {};
  const uint8_t* current = dictionary_.address(ref);
  const bool comparable = current != nullptr && ref.size() <= 8U;
  if (comparable) {
    copyBytes(before, current, ref.size());
  }
  const AbortCode result = hookFor(ref).write(dictionary_, ref, data, length);
  if (result != AbortCode::kNone) {
    return result;
  }
  return observer_->onWritten(ref, !comparable || !sameBytes(before, current, ref.size()));
}

AbortCode ObjectAccess::readStream(const od::EntryRef& ref, size_t offset, uint8_t* destination,
                                   size_t capacity, size_t* produced, size_t* totalSize) noexcept {
  *produced = 0;
  *totalSize = 0;
  return hookFor(ref).readStream(dictionary_, ref, offset, destination, capacity, produced,
                                 totalSize);
}

AbortCode ObjectAccess::writeStream(const od::EntryRef& ref, size_t offset, const uint8_t* source,
                                    size_t length, bool last, size_t indicatedSize) noexcept {
  return hookFor(ref).writeStream(dictionary_, ref, offset, source, length, last, indicatedSize);
}

void ObjectAccess::abortWriteStream(const od::EntryRef& ref, AbortCode reason) noexcept {
  hookFor(ref).abortWriteStream(dictionary_, ref, reason);
}

}  // namespace costa
