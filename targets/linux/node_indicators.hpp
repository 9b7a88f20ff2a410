// The CiA 303-3 indicators of a node of costa-slave (with --trace): costa::Indicators over the
// node, driving two simulated LEDs; each change of the LEDs' states is a trace line, for
// example "indicators RUN blinking, ERROR double flash".
#pragma once

#include <string>

#include "costa/indicators.hpp"

namespace costa::host {

/// The LEDs of a board that has none: their levels, kept.
class SimulatedLeds final : public IndicatorOutputs {
 public:
  void setRun(bool on) noexcept override { run = on; }
  void setError(bool on) noexcept override { error = on; }
  bool run = false;
  bool error = false;
};

class NodeIndicators {
 public:
  explicit NodeIndicators(Node& node) : indicators_(node, leds_) {}

  /// Indicators::process(); returns its next deadline.
  Microseconds process(Microseconds now) noexcept { return indicators_.process(now); }
  /// "RUN blinking, ERROR off" when the states changed since the last call, else "".
  std::string change();
  bool attached() const noexcept { return indicators_.attached(); }

 private:
  SimulatedLeds leds_;
  Indicators indicators_;
  bool shown_ = false;
  IndicatorState run_ = IndicatorState::kOff;
  IndicatorState error_ = IndicatorState::kOff;
};

/// "off", "flickering", "blinking", "single flash", ...
const char* indicatorStateName(IndicatorState state);

}  // namespace costa::host
