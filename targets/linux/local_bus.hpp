// The nodes of one costa-slave on one bus. A frame a node sends goes to the interface once and,
// when the interface took it, to every other node of the process, in the order the frames were
// put on the interface; a frame read from the interface goes to every node. Frames between the
// nodes are queued and delivered by process(), never from inside the sender's call (a node's
// transmit never re-enters another node).
//
// Event-driven: each node's next deadline is kept; process() runs only the nodes whose deadline
// has come, that used a frame since their last run, or whose frames the socket refused. A frame
// a node ignores (statistics().framesIgnored) leaves it alone. Due nodes run before the next
// queued frame is delivered (the clock is read again after each), so a node's timer waits for
// at most one delivery to every node, not for a whole burst of them.
#pragma once

#include <stddef.h>

#include <deque>
#include <memory>
#include <vector>

#include "costa/port/linux/monotonic_clock.hpp"
#include "costa/port/linux/socketcan_port.hpp"
#include "device_target.hpp"
#include "node_indicators.hpp"
#include "slave_tracer.hpp"

namespace costa::host {

class LocalBus {
 public:
  /// The nodes' time is the low 32 bits of `clock`.
  LocalBus(port::SocketCanPort& socket, SlaveTracer& tracer, port::LinuxMonotonicClock& clock)
      : socket_(socket), tracer_(tracer), clock_(clock) {}

  /// The transmitter of the next node (index nodeCount() at attach()). Stable address.
  CanTransmitter& nextPort();
  /// Adds the node built on the last nextPort().
  void attach(std::unique_ptr<DeviceTarget> target);

  size_t nodeCount() const { return nodes_.size(); }
  DeviceTarget& node(size_t index) { return *nodes_[index].target; }

  /// Powers every node on, in order (their boot-ups reach each other).
  void start(Microseconds now);
  /// A frame read from the interface: to every node.
  void receive(const CanFrame& frame, Microseconds now);
  /// A controller event of the interface: to every node.
  void controllerEvent(CanControllerEvent event, Microseconds now);
  /// Node `index` must run at the next process() (a control command changed it).
  void touch(size_t index) { nodes_[index].due = true; }
  /// Runs the nodes that are due and delivers the frames the nodes sent, one after the other,
  /// until no frame waits; returns the earliest deadline of all nodes.
  Microseconds process();
  /// Some node holds frames the interface refused.
  bool txPending() const;
  /// Offers the refused frames again.
  void flushTx();

 private:
  class Port final : public CanTransmitter {
   public:
    Port(LocalBus& bus, size_t index) : bus_(bus), index_(index) {}
    bool tryTransmit(const CanFrame& frame) noexcept override {
      return bus_.transmit(index_, frame);
    }

   private:
    LocalBus& bus_;
    size_t index_;
  };
  struct Sent {
    size_t sender = 0;
    CanFrame frame;
  };
  struct Slot {
    std::unique_ptr<DeviceTarget> target;
    Microseconds deadline = 0;
    bool due = true;
    bool refused = false;                        ///< the socket refused a frame: the node holds it
    std::unique_ptr<NodeIndicators> indicators;  ///< with --trace: its LEDs' states traced
  };

  bool transmit(size_t sender, const CanFrame& frame);
  /// Hands `frame` to node `index`; it is due when it used the frame.
  void deliver(size_t index, const CanFrame& frame, Microseconds now);
  /// Runs every node that is due at `now`.
  void runDue(Microseconds now);
  Microseconds now() const { return static_cast<Microseconds>(clock_.nowMicroseconds()); }

  port::SocketCanPort& socket_;
  SlaveTracer& tracer_;
  port::LinuxMonotonicClock& clock_;
  std::vector<std::unique_ptr<Port>> ports_;
  std::vector<Slot> nodes_;
  std::deque<Sent> sent_;
};

}  // namespace costa::host
