// The hot paths: seven operations of a node whose cost is budgeted (tools/budgets.txt), measured
// with one rule on x86-64 under callgrind (hot_paths_callgrind.cpp) and on Cortex-M under QEMU
// (hot_paths_firmware.cpp). Freestanding (no heap, no exceptions, no C library beyond
// <string.h>), so that the firmware runs the very code the host measures.
//
// The node: hot_paths.eds (CiA 301 communication objects plus 0x2000..0x2003), node-id 1,
// operational; RPDO1 0x201 -> 0x2000:01..02 (2 x UNSIGNED32), RPDO2 0x301 -> 0x2001:01..08
// (8 x UNSIGNED8), both type 254; TPDO1..4 on 0x181..0x481, type 1, two UNSIGNED32 of 0x2003
// each; 0x1017 = 0; no LSS, no storage. Its transmitter copies every frame into a ring and never
// refuses (RingTransmitter).
//
// The rule: an operation is its request frames, each handed to Node::onFrame(frame, now) with
// `now` 1 ms later than before; nothing else. The idle processing cycle is one
// Node::process(now), `now` 1 ms later, with nothing due; the empty operation is the measuring
// loop alone. Each operation is run many times in a row, and
//   net = (gross - empty) - requestFrames x (idle - empty)
// where gross is the cost of one run, loop included: what an operation adds to the processing
// cycles a main loop runs anyway, one per received frame. The idle row is (idle - empty).
//
// Before an operation is measured, one run is checked against the exact frames it must send and
// the values it must write, then it is warmed up and checked again (prepare()).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/node.hpp"
#include "hot_paths_od.hpp"

namespace costa::hotpaths {

/// The driver's transmit side as the measurement models it: every frame is copied into a ring.
class RingTransmitter final : public CanTransmitter {
 public:
  static constexpr uint32_t kSize = 64;  // a power of two

  bool tryTransmit(const CanFrame& frame) noexcept override {
    ring_[sent_ % kSize] = frame;
    ++sent_;
    return true;
  }
  /// Frames sent so far.
  uint32_t sent() const noexcept { return sent_; }
  /// Frame number `n` (0: the first ever sent); only the last kSize are kept.
  const CanFrame& frame(uint32_t n) const noexcept { return ring_[n % kSize]; }

 private:
  CanFrame ring_[kSize];
  uint32_t sent_ = 0;
};

using HotPathNode = NodeInstance<gen::hot_paths::Values, gen::hot_paths::Capacity>;

/// The node, its transmitter and its clock.
class Bench {
 public:
  static constexpr uint8_t kNodeId = 1;
  static constexpr Microseconds kStep = 1000;  ///< between two frames or cycles

  Bench() noexcept;
  Bench(const Bench&) = delete;
  Bench& operator=(const Bench&) = delete;
  ~Bench() = default;

  /// Power-on, operational, ten idle cycles. Null, or what went wrong.
  const char* start() noexcept;

  /// One request frame, 1 ms after the previous frame or cycle.
  void receive(const CanFrame& frame) noexcept {
    now_ += kStep;
    node_.onFrame(frame, now_);
  }
  /// One processing cycle, 1 ms after the previous frame or cycle.
  void cycle() noexcept {
    now_ += kStep;
    static_cast<void>(node_.process(now_));
  }

  HotPathNode& node() noexcept { return node_; }
  const RingTransmitter& can() const noexcept { return can_; }

 private:
  RingTransmitter can_;
  HotPathNode node_;
  Microseconds now_ = 0;
};

struct Operation {
  const char* key;         ///< row of tools/budgets.txt and of the tables
  const char* label;       ///< what the tables call it
  uint32_t requestFrames;  ///< frames per run: the processing cycles the net rule subtracts
  void (*run)(Bench& bench);
  /// Before a checked run: clears what the run must write (null: nothing to clear).
  void (*clear)(Bench& bench);
  /// After a checked run that started when `firstFrame` frames had been sent: null when the run
  /// sent exactly the frames and wrote exactly the values it must, else what is wrong.
  const char* (*verify)(Bench& bench, uint32_t firstFrame);
};

/// The empty operation, the idle cycle, then the seven operations (the empty one and the idle
/// cycle first: every net figure needs them). `count` receives the number of rows.
const Operation* operations(size_t* count) noexcept;

inline constexpr const char* kEmptyKey = "empty";
inline constexpr const char* kIdleKey = "idle";

/// Checks one run of `operation`, runs it `warmUpRuns` more times, checks one more run. Null
/// when both checks passed, else what went wrong.
const char* prepare(Bench& bench, const Operation& operation, uint32_t warmUpRuns) noexcept;

}  // namespace costa::hotpaths
