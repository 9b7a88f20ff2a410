// The behaviour behind a Santeng controller's objects (docs/errata-santeng.md): the runtime
// commands go to the power stage, the queries come back from it when they are read, and the
// commands with side effects act:
//
//   0x2000-0x2002  motion commands; each ends the channel's stop (0x200E)
//   0x2003         loads the channel's encoder counter (D9)
//   0x2005         user variables, mirrored into 0x2106 (also when an RPDO writes them, D11)
//   0x200C/0x200D  emergency stop latched until released: the power stage is off (B5)
//   0x200E         stops one channel until its next motion command (D1, B6)
//   0x2017         saves the configuration: the communication group, the configuration group
//                  (0x5000-0x5003) and the node-id and bit rate (LSS record) (D8, B13)
//   0x2100-0x2121  queries, refreshed when read (relative counters: since the last read, B4)
//   0x5000-0x5003  the RS232 utility's configuration: hidden from the bus (D13)
#pragma once

#include "costa/node.hpp"
#include "power_stage.hpp"
#include "santeng_od.hpp"

namespace costa::santeng {

/// The node of a Santeng controller: its generated dictionary, sized by it.
using SantengNode = NodeInstance<gen::santeng::Values, gen::santeng::Capacity>;

/// The storage group of the RS232 utility's configuration (0x5000-0x5003, the EDS's group 4).
inline constexpr uint8_t kConfigurationGroup = 4;
/// What 0x2017 saves: the communication group and the configuration.
inline constexpr uint32_t kSavedGroups =
    groupBit(od::kGroupCommunication) | groupBit(kConfigurationGroup);

class SantengDevice : public ObjectHook, public NodeEvents {
 public:
  /// Attaches itself to `node`.
  SantengDevice(SantengNode& node, PowerStage& stage) noexcept;

  /// Runs the power stage up to `now` in whole milliseconds and refreshes the queries. Returns
  /// kNever: the readings are brought up to date whenever they are read or sent.
  Microseconds process(Microseconds now) noexcept;

  /// The RS232 utility's settings, as the simulation sets them (santeng_control.hpp).
  /// Channel settings take effect at once; automatic start at the next boot-up.
  void setChannelMode(size_t channel, ChannelMode mode) noexcept;
  void setMaxRpm(size_t channel, uint16_t rpm) noexcept;
  void setEncoderLines(size_t channel, uint16_t lines) noexcept;
  void setAutomaticStart(bool on) noexcept;

  /// The emergency stop is latched (0x200C until 0x200D).
  bool emergencyStop() const noexcept { return emergencyStop_; }
  /// Every hook and the listener found room in the node (its NodeStatistics count refusals).
  bool attached() const noexcept { return attached_; }

  AbortCode prepareRead(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                        const ReadRequest& request) noexcept override;
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;
  void onResetApplication() noexcept override;
  void onResetCommunication() noexcept override;
  void onRpdoReceived(uint16_t communicationIndex) noexcept override;
  void onStoredParametersInvalid(uint8_t group, StoreResult result) noexcept override;

 private:
  /// Runs the power stage up to `now` (whole milliseconds) and publishes its readings.
  void advance(Microseconds now) noexcept;
  void commands(ChannelCommand (&out)[kChannels]) const noexcept;
  /// The readings and the flags into the query objects.
  void publish() noexcept;
  /// 0x2108/0x2109 sub-index `sub`: the counts since its previous read.
  void readRelative(uint16_t index, uint8_t sub) noexcept;
  AbortCode act(const od::EntryRef& ref) noexcept;
  AbortCode save() noexcept;
  void mirrorUserVariables() noexcept;

  Node& node_;
  gen::santeng::Values& values_;
  PowerStage& stage_;
  Microseconds simulated_ = 0;           ///< time up to which the power stage has run
  uint32_t milliseconds_ = 0;            ///< of the current second since power-on
  uint32_t seconds_ = 0;                 ///< since power-on (0x2119)
  int32_t encoderRead_[kChannels] = {};  ///< 0x2104 at the previous read of 0x2108
  int32_t hallRead_[kChannels] = {};     ///< 0x2105 at the previous read of 0x2109
  bool stopping_[kChannels] = {};        ///< 0x200E until the next motion command
  bool emergencyStop_ = false;
  bool configurationLost_ = false;  ///< stored configuration damaged: defaults (FF 0x80, B10)
  bool attached_;  ///< last: every other member is ready when the node gets the hooks
};

}  // namespace costa::santeng
