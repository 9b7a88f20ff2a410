// The CiA 303-3 indicator states of a node: the RUN and ERROR LEDs, derived from the node's
// NMT state, LSS, error control and CAN controller, and driven through IndicatorOutputs with
// the standard's timing. A layer over the node's public API (a listener), optional twice: an
// image that creates no Indicators links none of it, and a build without
// COSTA_FEATURE_INDICATORS compiles none of it (IndicatorsChoice below is then a stand-in that
// drives nothing).
//
//   pattern         the LED                                 RUN                ERROR
//   off             off                                     no node-id yet     no error
//   flickering      50 ms on, 50 ms off                     LSS configuration  (alternately)
//   blinking        200 ms on, 200 ms off                   pre-operational    -
//   single flash    200 ms on, 1000 ms off                  stopped            error passive
//   double flash    200 on, 200 off, 200 on, 1000 off       -                  error control event
//   triple flash    3 x (200 on, 200 off), the last 1000    -                  SYNC error
//   on              on                                      operational        bus-off
//
// ERROR shows the most severe condition: bus-off, then a SYNC error, then an error control
// event (a monitored heartbeat timed out, life guarding expired), then error passive (the
// controller's counters past the warning limit: the drivers report error passive, 128, not the
// warning level, 96). While the LSS slave is in configuration state both LEDs flicker, in
// opposite phase (ERROR still shows bus-off). A SYNC error: a SYNC consumer with a period in
// 0x1006 saw no SYNC for 1.5 periods since the last one (monitoring starts at the first SYNC
// and ends at reset communication). A pattern starts at its beginning when the LED's state
// changes.
//
// Context: the node's. Call process() after the node's onFrame()/process() and when its
// deadline comes; O(1).
#pragma once

#include <stdint.h>

#include "costa/compiled_out.hpp"
#include "costa/features.hpp"
#include "costa/node.hpp"
#include "costa/port/indicator_outputs.hpp"

namespace costa {

enum class IndicatorState : uint8_t {
  kOff,
  kFlickering,
  kBlinking,
  kSingleFlash,
  kDoubleFlash,
  kTripleFlash,
  kOn,
};

class Indicators final : public NodeEvents {
 public:
  /// Listens to `node` (attached() says whether it found room) and drives `outputs`; both LEDs
  /// start off.
  Indicators(Node& node, IndicatorOutputs& outputs) noexcept;

  bool attached() const noexcept { return attached_; }

  /// Updates both states and switches the LEDs whose pattern has an edge by `now`. Returns the
  /// time of the next edge or SYNC deadline (kNever: none).
  Microseconds process(Microseconds now) noexcept;

  IndicatorState run() const noexcept { return run_.state; }
  IndicatorState error() const noexcept { return error_.state; }

  void onSync(uint8_t counter) noexcept override;
  void onResetCommunication() noexcept override;
  void onHeartbeatTimeout(uint8_t nodeId) noexcept override;
  void onHeartbeatResumed(uint8_t nodeId) noexcept override;
  void onHeartbeatWithdrawn(uint8_t nodeId) noexcept override;
  void onLifeGuardingExpired() noexcept override { lifeGuardingExpired_ = true; }
  void onLifeGuardingResumed() noexcept override { lifeGuardingExpired_ = false; }

 private:
  /// One LED: its state, where it is in the state's pattern, and its level.
  struct Led {
    IndicatorState state = IndicatorState::kOff;
    uint8_t phase = 0;
    bool inverted = false;  ///< ERROR's flicker runs in opposite phase to RUN's
    bool level = false;
    Microseconds phaseEnd = kNever;
  };

  IndicatorState runState() const noexcept;
  IndicatorState errorState(Microseconds now) noexcept;
  /// Moves `led` to `state` (restarting its pattern on a change) and along its pattern to `now`;
  /// returns whether its level changed.
  static bool update(Led& led, IndicatorState state, bool inverted, Microseconds now) noexcept;

  Node& node_;
  IndicatorOutputs& outputs_;
  Led run_;
  Led error_;
  Microseconds syncDeadline_ = kNever;  ///< the SYNC error starts here; kNever: not monitored
  uint8_t heartbeatTimeouts_ = 0;       ///< monitored producers timed out now
  bool syncError_ = false;              ///< no SYNC within 1.5 periods, until the next one
  bool lifeGuardingExpired_ = false;
  bool attached_;  ///< last: the rest is ready when the node may call it
};

/// Indicators in a build without them (features::kIndicators false): nothing attached, both
/// states off, no output ever switched.
class AbsentIndicators {
 public:
  AbsentIndicators(Node& node, IndicatorOutputs& outputs) noexcept {
    (void)node;
    (void)outputs;
  }
  bool attached() const noexcept { return false; }
  Microseconds process(Microseconds now) noexcept {
    (void)now;
    return kNever;
  }
  IndicatorState run() const noexcept { return IndicatorState::kOff; }
  IndicatorState error() const noexcept { return IndicatorState::kOff; }
};

/// The LEDs an image drives when its build has them: Indicators, or the stand-in.
using IndicatorsChoice = ServiceIf<features::kIndicators, Indicators, AbsentIndicators>;

}  // namespace costa
