// The two CiA 303-3 indicators of a device: the green RUN LED and the red ERROR LED. A port
// switches its pins (or a bicolour LED's two halves); costa::Indicators decides when.
#pragma once

namespace costa {

class IndicatorOutputs {
 public:
  IndicatorOutputs(const IndicatorOutputs&) = delete;
  IndicatorOutputs& operator=(const IndicatorOutputs&) = delete;

  /// Switches the RUN LED (green). Called only on a change, from the node's context; must not
  /// block. The default drives nothing. (No pure virtual functions in port interfaces: firmware
  /// needs nothing from the C++ runtime library.)
  virtual void setRun(bool on) noexcept { (void)on; }
  /// Switches the ERROR LED (red), likewise.
  virtual void setError(bool on) noexcept { (void)on; }

 protected:
  IndicatorOutputs() = default;
  ~IndicatorOutputs() = default;
};

}  // namespace costa
