// One running SRDO (CiA 304): a transmit SRDO's schedule (its normal and inverted frames every
// SCT), or a receive SRDO's checks (the inverted frame within SRVT of the normal one, a new
// pair within SCT, the inverted data the bitwise NOT of the normal data, both of the mapping's
// length). What the data means (the mapped entries) is the safety service's business.
//
// Context: the one that runs the node. O(1) per frame and per deadline.
#pragma once

#include <stdint.h>

#include "costa/port/can_frame.hpp"
#include "costa/srdo_configuration.hpp"
#include "costa/srdo_failure.hpp"
#include "costa/time.hpp"

namespace costa {

class SrdoChannel {
 public:
  /// Starts at `now` (entering operational): a transmit SRDO is due at once, a receive SRDO
  /// expects its first pair within SCT.
  void start(const SrdoConfiguration& configuration, Microseconds now) noexcept;
  void stop() noexcept { running_ = false; }
  bool running() const noexcept { return running_; }
  const SrdoConfiguration& configuration() const noexcept { return configuration_; }

  /// Transmit SRDO: true when its pair is due at `now` (the next one is then due SCT later).
  bool transmitDue(Microseconds now) noexcept;
  /// Receive SRDO: the failure of a deadline passed at `now`, or kNone.
  SrdoFailure checkDeadlines(Microseconds now) const noexcept;
  /// Receive SRDO: a frame on its normal (`inverted` false) or inverted CAN-ID. kNone and
  /// *complete = true when it completes a valid pair, whose data is then data().
  SrdoFailure onFrame(const CanFrame& frame, bool inverted, Microseconds now,
                      bool* complete) noexcept;
  const uint8_t* data() const noexcept { return normal_; }

  Microseconds nextDeadline() const noexcept;

 private:
  SrdoConfiguration configuration_;
  Microseconds next_ = kNever;           ///< transmit: the next pair; receive: SCT's end
  Microseconds validationEnd_ = kNever;  ///< receive: SRVT's end while the inverted is due
  uint8_t normal_[8] = {};
  bool running_ = false;
};

}  // namespace costa
