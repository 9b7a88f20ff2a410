#include "node_indicators.hpp"

namespace costa::host {

const char* indicatorStateName(IndicatorState state) {
  switch (state) {
    case IndicatorState::kOff: return "off";
    case IndicatorState::kFlickering: return "flickering";
    case IndicatorState::kBlinking: return "blinking";
    case IndicatorState::kSingleFlash: return "single flash";
    case IndicatorState::kDoubleFlash: return "double flash";
    case IndicatorState::kTripleFlash: return "triple flash";
    case IndicatorState::kOn: return "on";
  }
  return "?";
}

std::string NodeIndicators::change() {
  const IndicatorState run = indicators_.run();
  const IndicatorState error = indicators_.error();
  if (shown_ && run == run_ && error == error_) {
    return "";
  }
  shown_ = true;
  run_ = run;
  error_ = error;
  return std::string("RUN ") + indicatorStateName(run) + ", ERROR " + indicatorStateName(error);
}

}  // namespace costa::host
