// The device under replay, as the replayer drives it: a device composition (targets/devices.hpp,
// as firmware and costa-slave run it) behind one interface.
#pragma once

#include <stddef.h>

#include "costa/port/can_frame.hpp"
#include "costa/time.hpp"
#include "fixed_text.hpp"

namespace costa::replay {

class ReplayDevice {
 public:
  virtual void start(Microseconds now) noexcept { (void)now; }
  virtual void onFrame(const CanFrame& frame, Microseconds now) noexcept {
    (void)frame;
    (void)now;
  }
  /// Runs node and device; returns the next deadline.
  virtual Microseconds process(Microseconds now) noexcept {
    (void)now;
    return kNever;
  }
  /// A `sim` command: the composition's control(). True when done; otherwise false with one
  /// line saying why not in `why`.
  virtual bool control(const char* command, Text& why) noexcept {
    (void)command;
    why.append("this device has no simulation commands");
    return false;
  }

 protected:
  ReplayDevice() = default;
  ~ReplayDevice() = default;
  ReplayDevice(const ReplayDevice&) = delete;
  ReplayDevice& operator=(const ReplayDevice&) = delete;
};

/// A composition as a ReplayDevice; constructed with the composition's own arguments.
template <typename Composition>
class ReplayedComposition final : public ReplayDevice {
 public:
  template <typename... Args>
  explicit ReplayedComposition(Args&... args) noexcept : composition_(args...) {}

  void start(Microseconds now) noexcept override { composition_.start(now); }
  void onFrame(const CanFrame& frame, Microseconds now) noexcept override {
    composition_.onFrame(frame, now);
  }
  Microseconds process(Microseconds now) noexcept override { return composition_.process(now); }
  bool control(const char* command, Text& why) noexcept override {
    char reason[96] = {};
    if (composition_.control(command, reason, sizeof(reason))) {
      return true;
    }
    why.append(reason);
    return false;
  }

  Composition& composition() noexcept { return composition_; }

 private:
  Composition composition_;
};

}  // namespace costa::replay
