// Which entries the SDO server streams through their hook instead of copying them whole.
#pragma once

#include <stddef.h>

#include "costa/od/entry_ref.hpp"

namespace costa {

/// DOMAINs (whose data lives with the application) and values larger than the SDO buffer are
/// moved piecewise through ObjectHook::readStream() and writeStream(); every other value is
/// copied whole through the buffer, so that a download is written only when complete.
inline bool sdoStreams(const od::EntryRef& ref, size_t bufferSize) noexcept {
  return ref.size() > bufferSize || ref.type() == od::DataType::kDomain;
}

}  // namespace costa
