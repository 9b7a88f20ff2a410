// LSS slave (CiA 305 Layer Setting Services): an LSS master on 0x7E5 inquires and changes this
// device's node-id and bit timing, and finds devices without a node-id by their identity
// (identify services, LSS Fastscan). Responses go on 0x7E4.
//
// The class is a service of the node, driven like the others:
//
//   lss.reset(identity, nodeId, nodeId, bitTiming);  // power-on and every reset communication
//   lss.onFrame(frame, now);                         // every frame received on 0x7E5
//   lss.process(now);                                // no later than lss.nextDeadline()
//
// What only the device knows (supported bit rates, non-volatile storage, the CAN controller,
// NMT resets) it asks of an LssSlaveHost. Every frame it sends goes to the TransmitPath given
// at construction: COB-ID 0x7E4, DLC 8, bytes it does not use zero.
#pragma once

#include <stdint.h>

#include "costa/cob_ids.hpp"
#include "costa/lss_bit_timing.hpp"
#include "costa/port/can_frame.hpp"
#include "costa/time.hpp"
#include "costa/transmit_path.hpp"

namespace costa {

/// The LSS address: the identity object 0x1018 sub-indices 1..4.
struct LssIdentity {
  uint32_t vendorId = 0;
  uint32_t productCode = 0;
  uint32_t revisionNumber = 0;
  uint32_t serialNumber = 0;
};

/// Outcome of store configuration: the CiA 305 error code sent in byte 1 of the response.
enum class LssStoreResult : uint8_t {
  kStored = 0,              ///< Protocol successfully completed.
  kNotSupported = 1,        ///< Store configuration is not supported.
  kStorageAccessError = 2,  ///< Storage media access error.
};

/// The LSS slave state machine of CiA 305 (its initial and final pseudo states aside).
enum class LssState : uint8_t { kWaiting = 0, kConfiguration = 1 };

/// What an LssSlave needs from the device. Implemented by the node (or the device behind it);
/// every default is an inert device: no bit timing supported, nothing stored, no autonomous
/// reset. Called synchronously from LssSlave::onFrame() or process(); must not block.
class LssSlaveHost {
 public:
  /// Configure bit timing: can the device run at `timing`? Asked only for table selector 0 with
  /// a defined index (0..4, 6..9) and for manufacturer tables (selectors 128..255); reserved
  /// selectors and indices are refused without asking. Default: false.
  virtual bool bitTimingSupported(LssBitTiming timing) noexcept {
    (void)timing;
    return false;
  }

  /// Activate bit timing, after the first switch delay: switch the CAN controller to `timing`
  /// (the last one configured, else the one given to LssSlave::reset()). The device sends
  /// nothing until LssSlave::transmissionSuspended() turns false. Default: does nothing.
  virtual void activateBitTiming(LssBitTiming timing) noexcept { (void)timing; }

  /// Store configuration: write the pending node-id (1..127 or 0xFF) and `timing` (the pending
  /// bit timing) to non-volatile memory, for use from the next power-on. Its result is sent to
  /// the master unchanged. Default: kNotSupported.
  virtual LssStoreResult storeConfiguration(uint8_t nodeId, LssBitTiming timing) noexcept {
    (void)nodeId;
    (void)timing;
    return LssStoreResult::kNotSupported;
  }

  /// Switch state global to waiting has just left the configuration state of a device that had
  /// no active node-id (0xFF) and now has a valid pending one: CiA 305 asks the device to run
  /// NMT reset communication now, which applies the new node-id (and calls LssSlave::reset()).
  /// Called as the last step of LssSlave::onFrame(), so calling reset() from here is safe.
  /// Default: does nothing (the node-id then applies at the next reset communication).
  virtual void requestResetCommunication() noexcept {}

 protected:
  LssSlaveHost() = default;
  ~LssSlaveHost() = default;
  LssSlaveHost(const LssSlaveHost&) = default;
  LssSlaveHost& operator=(const LssSlaveHost&) = default;
  LssSlaveHost(LssSlaveHost&&) = default;
  LssSlaveHost& operator=(LssSlaveHost&&) = default;
};

/// The slave side of every CiA 305 service. Services by LSS state (CiA 305 table "LSS services
/// in LSS states"); a request for a service the current state does not offer is ignored:
///
/// | service                                        | cs         | waiting | configuration |
/// |------------------------------------------------|------------|---------|---------------|
/// | switch state global                            | 0x04       | yes     | yes           |
/// | switch state selective                         | 0x40..0x43 | yes     | no            |
/// | configure node-id                              | 0x11       | no      | yes           |
/// | configure bit timing                           | 0x13       | no      | yes           |
/// | activate bit timing                            | 0x15       | no      | yes           |
/// | store configuration                            | 0x17       | no      | yes           |
/// | inquire vendor/product/revision/serial/node-id | 0x5A..0x5E | no      | yes           |
/// | identify remote slave                          | 0x46..0x4B | yes     | yes           |
/// | identify non-configured remote slave           | 0x4C       | yes     | yes           |
/// | LSS Fastscan                                   | 0x51       | yes     | no            |
///
/// Node-ids. The *active* node-id is the one the node runs with; the *pending* node-id is the
/// one configure node-id sets and that becomes active at the next NMT reset communication (the
/// node reads pendingNodeId() and passes it back to reset()). Inquire node-id reports the
/// active node-id, as CiA 305 specifies: after configure node-id it still reports the old one
/// until reset communication. A device takes part in identify non-configured remote slave and
/// in Fastscan only while it is non-configured: both its active and its pending node-id are
/// 0xFF, so a device that has just been given a node-id drops out of the next Fastscan round.
///
/// No heap, no blocking; every call is O(1).
class LssSlave {
 public:
  /// Until reset() is called the slave is in LSS waiting state with a zero identity and node-id
  /// 0xFF (active and pending).
  LssSlave(TransmitPath& tx, LssSlaveHost& host) noexcept;
  LssSlave(const LssSlave&) = delete;
  LssSlave& operator=(const LssSlave&) = delete;
  ~LssSlave() = default;

  /// Power-on and every NMT reset communication: LSS waiting state, this identity, these
  /// node-ids (1..127, or 0xFF for none) and `bitTiming` as the running (and pending) bit
  /// timing. Forgets partial switch state selective, identify remote slave and Fastscan
  /// sequences and cancels a bit timing switch in progress. Sends nothing; may be called from
  /// within LssSlaveHost::requestResetCommunication(). O(1).
  void reset(const LssIdentity& identity, uint8_t activeNodeId, uint8_t pendingNodeId,
             LssBitTiming bitTiming) noexcept;

  /// Handles a frame received on 0x7E5 and queues the response, if the service has one, before
  /// returning. Returns false, changing nothing and sending nothing, when the frame is not a
  /// request this slave accepts now: another COB-ID, an extended id, RTR, DLC other than 8, an
  /// unknown command specifier, a service the current LSS state does not offer (table above),
  /// switch state global with a mode other than 0 or 1, a Fastscan request with BitChecked
  /// other than 0..31 and 0x80 or LSSSub/LSSNext above 3, and any frame while a bit timing
  /// switch is in progress (transmissionSuspended()). A valid request whose identity or range
  /// does not match this device, or a Fastscan or identify non-configured remote slave request
  /// reaching a device that has a node-id, returns true and sends nothing. Any content is safe.
  /// O(1).
  ///
  /// Responses (byte 0 is the command specifier, other bytes 0 unless given):
  /// * switch state selective: 0x44 after vendor (0x40), product (0x41), revision (0x42) and
  ///   serial (0x43) have matched in this order; the slave enters LSS configuration state. A
  ///   mismatch or a frame out of order starts over (0x40 always starts a new sequence).
  /// * configure node-id: 0x11, byte 1 = 0 (accepted: 1..127 or 0xFF becomes the pending
  ///   node-id) or 1 (out of range, nothing changes).
  /// * configure bit timing: 0x13, byte 1 = 0 (becomes the pending bit timing) or 1 (not
  ///   supported; see LssSlaveHost::bitTimingSupported()).
  /// * activate bit timing (bytes 1..2: switch delay in ms): no response. The slave stops
  ///   transmitting, after one delay calls LssSlaveHost::activateBitTiming() from process(),
  ///   and resumes transmitting after a second delay.
  /// * store configuration: 0x17, byte 1 = LssSlaveHost::storeConfiguration()'s result.
  /// * inquire identity: 0x5A..0x5D, bytes 1..4 = vendor-id, product code, revision number,
  ///   serial number (little-endian); inquire node-id: 0x5E, byte 1 = the active node-id.
  /// * identify remote slave: 0x4F after vendor-id (0x46) and product code (0x47) have matched
  ///   and the revision number lies in [0x48, 0x49] and the serial number in [0x4A, 0x4B]
  ///   (bounds included), the six frames in this order; as for switch state selective, a
  ///   mismatch or a frame out of order starts over.
  /// * identify non-configured remote slave: 0x50 when the device is non-configured.
  /// * LSS Fastscan (bytes 1..4 IDNumber, 5 BitChecked, 6 LSSSub, 7 LSSNext), non-configured
  ///   devices only: BitChecked 0x80 restarts the scan at the vendor-id and is answered 0x4F.
  ///   Otherwise, when LSSSub is the identity value the scan has reached and IDNumber equals
  ///   that value in bits 31..BitChecked, the slave answers 0x4F and moves the scan to LSSNext;
  ///   when BitChecked is 0 and LSSNext < LSSSub the whole identity is confirmed and the slave
  ///   enters LSS configuration state.
  /// * switch state global (byte 1: 0 = waiting, 1 = configuration): no response. Leaving
  ///   configuration for waiting with active node-id 0xFF and a valid pending node-id calls
  ///   LssSlaveHost::requestResetCommunication().
  [[nodiscard]] bool onFrame(const CanFrame& frame, Microseconds now) noexcept;

  /// Runs the bit timing switch when due: calls LssSlaveHost::activateBitTiming() after the
  /// first switch delay and ends the transmit suspension after the second (both in one call
  /// when `now` is past both). Sends nothing. O(1).
  void process(Microseconds now) noexcept;

  /// When process() has work next (the end of the current switch delay), or kNever.
  Microseconds nextDeadline() const noexcept;

  LssState state() const noexcept { return state_; }
  bool configurationState() const noexcept { return state_ == LssState::kConfiguration; }

  /// The node-id the node runs with, as given to reset(); what inquire node-id reports.
  uint8_t activeNodeId() const noexcept { return activeNodeId_; }
  /// The node-id to apply at the next reset communication (1..127, or 0xFF for none).
  uint8_t pendingNodeId() const noexcept { return pendingNodeId_; }
  /// The bit timing activate bit timing and store configuration use.
  LssBitTiming pendingBitTiming() const noexcept { return pendingBitTiming_; }
  /// Neither the active nor the pending node-id is valid: the device takes part in Fastscan
  /// and answers identify non-configured remote slave.
  bool nonConfigured() const noexcept;

  /// True from activate bit timing until the second switch delay has passed: the node must
  /// send nothing (no heartbeat, no queued frame) meanwhile, and the slave ignores frames.
  bool transmissionSuspended() const noexcept { return switchPhase_ != SwitchPhase::kIdle; }

  const LssIdentity& identity() const noexcept { return identity_; }

  /// Consistency of the state machine (for tests and fuzzing): a defined LSS state, active and
  /// pending node-ids of 1..127 or 0xFF, sequence positions within their sequences, and a bit
  /// timing switch with its times set in order. O(1), changes nothing.
  bool valid() const noexcept;

 private:
  enum class SwitchPhase : uint8_t { kIdle, kBeforeSwitch, kAfterSwitch };

  bool handleWaiting(const uint8_t* request) noexcept;
  bool handleConfiguration(const uint8_t* request, Microseconds now) noexcept;
  bool handleEitherState(const uint8_t* request) noexcept;
  bool switchStateGlobal(uint8_t mode) noexcept;
  void switchStateSelective(uint8_t cs, uint32_t value) noexcept;
  void configureNodeId(uint8_t nodeId) noexcept;
  void configureBitTiming(LssBitTiming timing) noexcept;
  void activateBitTiming(uint16_t delayMs, Microseconds now) noexcept;
  void identifyRemoteSlave(uint8_t cs, uint32_t value) noexcept;
  bool fastscan(const uint8_t* request) noexcept;

  uint32_t identityValue(uint8_t sub) const noexcept;
  void respond(uint8_t cs, uint8_t byte1 = 0) noexcept;
  void respondValue(uint8_t cs, uint32_t value) noexcept;

  TransmitPath& tx_;
  LssSlaveHost& host_;
  LssIdentity identity_;
  LssState state_ = LssState::kWaiting;
  uint8_t activeNodeId_ = cob::kLssUnconfigured;
  uint8_t pendingNodeId_ = cob::kLssUnconfigured;
  LssBitTiming pendingBitTiming_;
  uint8_t selectiveMatched_ = 0;  ///< Switch state selective frames matched in order (0..3).
  uint8_t identifyMatched_ = 0;   ///< Identify remote slave frames matched in order (0..5).
  uint8_t fastscanPosition_ = 0;  ///< LSSPos: the identity value Fastscan has reached (0..3).
  SwitchPhase switchPhase_ = SwitchPhase::kIdle;
  Microseconds switchAt_ = kNever;
  Microseconds resumeAt_ = kNever;
};

}  // namespace costa
