// The behaviour behind the SOLO's objects: references and modes go to the drive backend, its
// measurements come back into the dictionary, and the objects with side effects act.
//
//   0x3001  new device address: taken at the next reset (errata S11), kept across resets (M)
//   0x3007  motor identification: after 1 s, resistance 0x300D and inductance 0x300E
//   0x3009  PWM frequency: written in kHz (8..80), read in Hz (errata D8)
//   0x3014  reset factory: defaults at the next power-up (stored parameters are discarded)
//   0x301F  home: the position counter becomes 0
//   0x3020  device error register: writable (overwrite errors); see SoloErrorRegister
//   0x304A  analogue input: the channel is the upload request's data (errata P9)
//   life time expiry: 0x3020 bit 5, and the drive stops until the register is cleared (S5)
#pragma once

#include "costa/node.hpp"
#include "drive_backend.hpp"
#include "solo_error_register.hpp"
#include "solo_od.hpp"

namespace costa::solo {

/// The node of a SOLO: its generated dictionary, sized by it.
using SoloNode = NodeInstance<gen::solo::Values, gen::solo::Capacity>;

class SoloDevice : public ObjectHook, public NodeEvents {
 public:
  /// The drive is simulated in steps of this length.
  static constexpr Microseconds kStep = 10000;
  /// While the drive rests, process() still asks for a step this often (10 min).
  static constexpr Microseconds kLongestRest = 60000U * kStep;

  /// Attaches itself to `node`. `powerOnNodeId` is the address when 0x3001 holds nothing
  /// stored, or always when `nodeIdGiven` (DeviceConfig::nodeIdGiven: costa-slave --node-id).
  SoloDevice(SoloNode& node, DriveBackend& drive, uint8_t powerOnNodeId, bool nodeIdGiven) noexcept;

  /// Runs the drive up to `now`; returns the next step. While the drive rests (a step changed
  /// nothing, and nothing it depends on changed since) it asks for a step only every
  /// kLongestRest. Call it after every frame: a change made while the drive rests takes effect
  /// from the next step on, as if every step had been taken.
  Microseconds process(Microseconds now) noexcept;
  /// The deadline process() returned, checked again: the node's own processing may have changed
  /// the command since (life guarding stops the drive).
  Microseconds nextDeadline() noexcept;

  /// Called when 0x3014 asks for factory defaults (the target discards stored parameters);
  /// false when that failed: the write answers 0x08000020.
  using FactoryResetHandler = bool (*)(void* context) noexcept;
  void onFactoryReset(FactoryResetHandler handler, void* context) noexcept {
    factoryReset_ = handler;
    factoryResetContext_ = context;
  }

  /// The hook and the listener found room in the node (its NodeStatistics count refusals).
  bool attached() const noexcept { return attached_; }

  AbortCode prepareRead(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                        const ReadRequest& request) noexcept override;
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;
  void onResetApplication() noexcept override;
  void onLifeGuardingExpired() noexcept override;

 private:
  DriveCommand command() const noexcept;
  /// The drive still rests: it rests under `command` (DriveBackend::restsUnder), and the
  /// register shows every fault it measured.
  bool stillResting(const DriveCommand& command) const noexcept;
  void publish(const DriveFeedback& feedback) noexcept;
  void storeSfxt(uint16_t index, double value) noexcept;
  uint32_t readU32(uint16_t index) const noexcept;

  Node& node_;
  gen::solo::Values& values_;
  DriveBackend& drive_;
  SoloErrorRegister errors_;
  uint8_t powerOnNodeId_;
  bool nodeIdGiven_;
  Microseconds simulated_ = 0;  ///< time up to which the drive has run
  Microseconds identifyAt_ = kNever;
  /// The drive rests (stillResting()): no steps until that changes.
  bool resting_ = false;
  uint32_t publishedFaults_ = 0;  ///< the faults the drive measured at the last step
  FactoryResetHandler factoryReset_ = nullptr;
  void* factoryResetContext_ = nullptr;
  bool attached_;  ///< last: every other member is ready when the node gets the hooks
};

}  // namespace costa::solo
