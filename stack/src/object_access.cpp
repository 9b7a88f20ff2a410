#include "costa/object_access.hpp"

#include <string.h>

namespace costa {

AbortCode ObjectAccess::prepareRead(uint16_t index, uint8_t subIndex, const ReadRequest& request,
                                    od::EntryRef* out) noexcept {
  const AbortCode found = dictionary_.find(index, subIndex, out);
  if (found != AbortCode::kNone) {
    return found;
  }
  if ((out->attributes() & od::kReadable) == 0U) {
    return AbortCode::kReadOfWriteOnly;
  }
  ObjectHook* hook = hooks_.find(index);
  return hook == nullptr ? AbortCode::kNone : hook->prepareRead(dictionary_, *out, request);
}

AbortCode ObjectAccess::locateForWrite(uint16_t index, uint8_t subIndex,
                                       od::EntryRef* out) const noexcept {
  const AbortCode found = dictionary_.find(index, subIndex, out);
  if (found != AbortCode::kNone) {
    return found;
  }
  if ((out->attributes() & od::kWritable) == 0U) {
    return AbortCode::kWriteOfReadOnly;
  }
  return AbortCode::kNone;
}

ObjectHook& ObjectAccess::hookFor(const od::EntryRef& ref) noexcept {
  ObjectHook* hook = hooks_.find(ref.index());
  if (hook == nullptr) {
    return plain_;
  }
  return *hook;
}

AbortCode ObjectAccess::write(const od::EntryRef& ref, const uint8_t* data,
                              size_t length) noexcept {
  // Small values are compared before and after, so that observers can skip unchanged ones.
  uint8_t before[8] = {};
  const uint8_t* current = dictionary_.address(ref);
  const bool comparable = observer_ != nullptr && current != nullptr && ref.size() <= 8U;
  if (comparable) {
    memcpy(before, current, ref.size());
  }
  const AbortCode result = hookFor(ref).write(dictionary_, ref, data, length);
  if (result == AbortCode::kNone && observer_ != nullptr) {
    const bool changed = !comparable || memcmp(before, current, ref.size()) != 0;
    observer_->onWritten(ref, changed);
  }
  return result;
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
