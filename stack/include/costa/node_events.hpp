// What a device application hears from its node.
#pragma once

#include "costa/nmt_state.hpp"

namespace costa {

/// Implemented by a device application and passed to `Node::setEvents()`. Called synchronously
/// from `Node::start()`, `onFrame()` or `process()`; must not block. Defaults do nothing.
class NodeEvents {
 public:
  /// The NMT state changed (also on the way through resets).
  virtual void onNmtStateChanged(NmtState previous, NmtState current) noexcept {
    (void)previous;
    (void)current;
  }
  /// Reset application (power-on or NMT reset node): the manufacturer and profile areas have just
  /// been set to their power-on values; re-initialise the device behind them.
  virtual void onResetApplication() noexcept {}
  /// Reset communication: the communication area (0x1000..0x1FFF) has just been set to its
  /// power-on values; the boot-up frame follows.
  virtual void onResetCommunication() noexcept {}

 protected:
  NodeEvents() = default;
  ~NodeEvents() = default;
  NodeEvents(const NodeEvents&) = default;
  NodeEvents& operator=(const NodeEvents&) = default;
};

}  // namespace costa
