// Which hook handles which indices.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/hot_path.hpp"
#include "costa/object_hook.hpp"

namespace costa {

struct HookBinding {
  uint16_t first = 0;
  uint16_t last = 0;
  ObjectHook* hook = nullptr;
};

/// Fixed-capacity list of (index range → hook) bindings over caller-owned storage. The most
/// recently attached binding that covers an index wins, so an application can override a
/// service's own object. Lookup is linear in the number of bindings (a few dozen at most).
class HookRegistry {
 public:
  HookRegistry(HookBinding* storage, size_t capacity) noexcept
      : bindings_(storage), capacity_(capacity) {}

  /// Returns false when full.
  bool attach(uint16_t first, uint16_t last, ObjectHook& hook) noexcept {
    if (count_ == capacity_) {
      return false;
    }
    bindings_[count_] = HookBinding{first, last, &hook};
    ++count_;
    return true;
  }

  /// The hook covering `index`, or nullptr.
  COSTA_SHARED_INLINE ObjectHook* find(uint16_t index) const noexcept {
    for (size_t i = count_; i > 0U; --i) {
      const HookBinding& binding = bindings_[i - 1U];
      if (index >= binding.first && index <= binding.last) {
        return binding.hook;
      }
    }
    return nullptr;
  }

  size_t size() const noexcept { return count_; }

 private:
  HookBinding* bindings_;
  size_t capacity_;
  size_t count_ = 0;
};

}  // namespace costa
