// EMCY producer (CiA 301 7.2.7): error conditions, the error register 0x1001, the pre-defined
// error field 0x1003, the EMCY COB-ID 0x1014 and inhibit time 0x1015.
//
// Context: the one that runs the node, never an interrupt; not reentrant (an interrupt that
// detects an error sets a flag the main loop turns into raise()). No allocation: conditions
// and the queue of frames waiting for their inhibit time live in caller-owned storage
// (NodeMemory). Nothing blocks and nothing is lost silently: a full condition table still sends
// the EMCY (counted: conditionsFull()), a full queue drops the frame (counted: lost()).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/emcy_profile.hpp"
#include "costa/nmt_state.hpp"
#include "costa/node_clock.hpp"
#include "costa/object_hook.hpp"
#include "costa/transmit_path.hpp"

namespace costa {

/// Error register bits (0x1001, CiA 301 table "Error register").
enum ErrorRegisterBit : uint8_t {
  kErrorGeneric = 1U << 0,
  kErrorCurrent = 1U << 1,
  kErrorVoltage = 1U << 2,
  kErrorTemperature = 1U << 3,
  kErrorCommunication = 1U << 4,
  kErrorDeviceProfile = 1U << 5,
  kErrorManufacturer = 1U << 7,
};

/// The error register bit CiA 301 associates with an error code's class: 0x2xxx current,
/// 0x3xxx voltage, 0x4xxx temperature, 0x81xx/0x82xx communication, 0xFxxx manufacturer-specific;
/// 0 for the others (the generic bit, which every condition sets, is not included).
uint8_t errorRegisterBitFor(uint16_t code) noexcept;

/// An active error condition. `source` tells apart conditions sharing a code (for example one
/// heartbeat consumer entry from another). Aligned as a word: clearing one moves the last into
/// its place with one load and one store.
struct alignas(4) EmcyCondition {
  uint16_t code = 0;
  uint8_t source = 0;
  uint8_t registerBits = 0;
};

/// An EMCY waiting for its inhibit time or for a state that allows EMCY.
struct PendingEmcy {
  uint8_t data[8] = {};
};

class EmcyProducer : public ObjectHook {
 public:
  static constexpr uint16_t kErrorRegisterIndex = 0x1001;
  static constexpr uint16_t kErrorHistoryIndex = 0x1003;
  static constexpr uint16_t kCobIdIndex = 0x1014;
  static constexpr uint16_t kInhibitIndex = 0x1015;

  EmcyProducer(od::ObjectDictionary& dictionary, const EmcyProfile& profile, NodeClock& clock,
               EmcyCondition* conditions, size_t conditionCapacity, PendingEmcy* pending,
               size_t pendingCapacity) noexcept
      : dictionary_(dictionary),
        profile_(profile),
        clock_(clock),
        conditions_(conditions),
        capacity_(conditionCapacity),
        pending_(pending),
        pendingCapacity_(pendingCapacity) {}

  void setNodeId(uint8_t nodeId) noexcept { nodeId_ = nodeId; }

  /// Reset communication: pending frames are dropped; active conditions stay (they describe
  /// the device) and the error register is rewritten. O(conditions).
  void onResetCommunication() noexcept;

  /// Raises a condition and queues its EMCY (once: raising an active condition does nothing).
  /// `manufacturer` (5 bytes, may be null) fills the manufacturer-specific field. Returns false
  /// when the condition was already active or the table is full (the EMCY is still sent).
  /// O(conditions + 0x1003 entries).
  bool raise(uint16_t code, uint8_t source, uint8_t registerBits,
             const uint8_t* manufacturer = nullptr) noexcept;
  /// Clears a condition; when it was the last one, queues the error-reset EMCY (code 0x0000).
  /// Returns false when the condition was not active. O(conditions).
  bool clear(uint16_t code, uint8_t source) noexcept;
  /// An error event without a lasting condition: one EMCY, recorded in 0x1003.
  /// O(0x1003 entries).
  void signal(uint16_t code, uint8_t registerBits, const uint8_t* manufacturer = nullptr) noexcept;

  bool active(uint16_t code, uint8_t source) const noexcept {
    return position(code, source) != count_;
  }
  size_t activeCount() const noexcept { return count_; }
  uint8_t errorRegister() const noexcept {
    return count_ == 0U ? uint8_t{0} : frameRegister(0);  // 0 without an active condition
  }
  /// EMCY frames that could not be queued (queue full), since construction.
  uint32_t lost() const noexcept { return lost_; }
  /// Conditions raised while the condition table was full (their EMCY went out, but clearing
  /// them sends no error reset), since construction.
  uint32_t conditionsFull() const noexcept { return conditionsFull_; }

  /// Sends queued EMCY frames when `state` allows (pre-operational, operational) and the
  /// inhibit time (0x1015) has passed since the previous one. O(frames sent).
  void process(Microseconds now, NmtState state, TransmitPath& tx) noexcept;
  /// When process() has something to send in `state`: now-or-earlier, the end of the inhibit
  /// time, or kNever (nothing queued, or a state without EMCY). O(1).
  Microseconds nextDeadline(NmtState state) const noexcept;

  /// 0x1003 (writing 0 to sub-index 0 clears the history; any other value aborts 0x06090030, any
  /// other length 0x06070012/0x06070013), 0x1014 (the CAN-ID of a valid EMCY cannot change; 29-bit
  /// refused; a valid EMCY cannot have a restricted CAN-ID: cob::acceptableCobId).
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;

 private:
  /// Where condition (`code`, `source`) is in the table; count_ when it is not active.
  size_t position(uint16_t code, uint8_t source) const noexcept;
  void enqueue(uint16_t code, uint8_t registerValue, const uint8_t* manufacturer) noexcept;
  /// The register byte of an EMCY raised with `registerBits`: the generic bit, `registerBits` and
  /// those of the active conditions (0 when the profile reports no register).
  uint8_t frameRegister(uint8_t registerBits) const noexcept;
  void record(uint16_t code, const uint8_t* manufacturer) noexcept;
  void publishRegister() noexcept;
  uint32_t cobId() const noexcept;

  uint8_t nodeId_ = 0;  // (first: within reach of Thumb-1's short offsets for a byte)
  od::ObjectDictionary& dictionary_;
  const EmcyProfile& profile_;
  NodeClock& clock_;
  EmcyCondition* conditions_;
  size_t capacity_;
  size_t count_ = 0;
  PendingEmcy* pending_;
  size_t pendingCapacity_;
  size_t pendingHead_ = 0;
  size_t pendingCount_ = 0;
  uint32_t lost_ = 0;
  uint32_t conditionsFull_ = 0;
  Microseconds nextAllowed_ = kNever;  ///< end of the inhibit time of the last EMCY sent
};

}  // namespace costa
