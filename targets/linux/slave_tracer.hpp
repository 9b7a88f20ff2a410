// costa-slave --trace: one line per frame (time, direction, frame, meaning), per controller
// event, per change of the loss counters and per bit rate switch. With several nodes each
// frame's line names the node it concerns: "@05 tx 705 [1] 05" (the sender; for a received
// frame the node its CAN-ID addresses, "@--" when none).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <memory>
#include <string>
#include <vector>

#include "costa/port/linux/monotonic_clock.hpp"
#include "costa/port/linux/socketcan_port.hpp"
#include "device_target.hpp"
#include "frame_trace.hpp"
#include "slave_counters.hpp"

namespace costa::host {

class SlaveTracer {
 public:
  /// `labelled`: lines name their node (several nodes).
  SlaveTracer(bool enabled, bool labelled, port::LinuxMonotonicClock& clock);

  /// Adds the next node (in the order of the nodes' indices).
  void attach(DeviceTarget& target);

  /// A frame node `index` sent (it is on the interface).
  void sent(size_t index, const CanFrame& frame);
  /// A frame read from the interface.
  void received(const CanFrame& frame);
  /// An error frame of the driver and the controller events it reported.
  void errorFrame(const port::SocketCanEvents& events);
  /// The counters of losses, when they changed since the last call.
  void counters(const SlaveCounters& now);
  /// "bit rate now 500 kbit/s": a node re-timed the port.
  void bitRate(uint32_t bitsPerSecond);
  /// Node `index`'s CiA 303-3 indicators changed: "indicators RUN blinking, ERROR off".
  void indicators(size_t index, const std::string& states);
  bool enabled() const { return enabled_; }

 private:
  struct Traced {
    DeviceTarget* target;
    std::unique_ptr<FrameTracer> decoder;
  };

  void frameLine(const char* direction, const Traced* node, const CanFrame& frame);
  /// "@05 " for a node, "@-- " for none, "" when lines are not labelled.
  std::string label(const Traced* node) const;
  /// The node whose node-id the CAN-ID of `frame` carries (a received frame), or null.
  Traced* addressed(const CanFrame& frame);
  void print(const std::string& label, const char* direction, const std::string& what,
             const std::string& meaning);

  bool enabled_;
  bool labelled_;
  port::LinuxMonotonicClock& clock_;
  uint64_t epoch_;
  std::vector<Traced> nodes_;
  FrameTracer generic_{nullptr, nullptr};  ///< frames of no node of the process (NMT, SYNC)
  SlaveCounters shown_;
};

}  // namespace costa::host
