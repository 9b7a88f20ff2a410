#include "costa/object_access.hpp"

#include <string.h>

namespace costa {

AbortCode ObjectAccess::prepareRead(uint16_t index, uint8_t subIndex, const ReadRequest& request,
                                    od::EntryRef* out) noexcept {
  const AbortCode found = dictionary_.find(index, subIndex, out);
  if (found != AbortCode::kNone) {
    return found;
  }
  if ((out->entry->attributes & od::kReadable) == 0U) {
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
  if ((out->entry->attributes & od::kWritable) == 0U) {
    return AbortCode::kWriteOfReadOnly;
  }
  return AbortCode::kNone;
}

AbortCode ObjectAccess::write(const od::EntryRef& ref, const uint8_t* data,
                              size_t length) noexcept {
  // Small values are compared before and after, so that observers can skip unchanged ones.
  uint8_t before[8] = {};
  const uint8_t* current = dictionary_.address(*ref.entry);
  const bool comparable = observer_ != nullptr && current != nullptr && ref.entry->size <= 8U;
  if (comparable) {
    memcpy(before, current, ref.entry->size);
  }
  ObjectHook* hook = hooks_.find(ref.index());
  const AbortCode result = hook == nullptr ? dictionary_.write(*ref.entry, data, length)
                                           : hook->write(dictionary_, ref, data, length);
  if (result == AbortCode::kNone && observer_ != nullptr) {
    const bool changed = !comparable || memcmp(before, current, ref.entry->size) != 0;
    observer_->onWritten(ref, changed);
  }
  return result;
}

}  // namespace costa
