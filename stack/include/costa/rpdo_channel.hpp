// One receive PDO (CiA 301 7.2.2): communication parameter 0x1400+n, mapping 0x1600+n (or the
// device's static mapping), resolved into where each entry's bytes go when configured.
//
// An RPDO is written whole or not at all: every entry is checked first (PdoMap::check), the
// listeners hear onRpdoWriting, the entries are written, then onRpdoReceived. An entry refused
// by its hook leaves every entry as it was; the RPDO is counted (PdoEngine::rpdosRefused()) and
// no listener hears of it.
//
// Context: the one that runs the node. No allocation. onFrame()/onSync() are O(mapped
// entries); with a plain mapping (no hook, no limits) a copy per entry.
#pragma once

#include <stdint.h>

#include "costa/hot_path.hpp"
#include "costa/node_events.hpp"
#include "costa/od/bytes.hpp"
#include "costa/pdo_channel.hpp"
#include "costa/port/can_frame.hpp"
#include "costa/time.hpp"

namespace costa {

class RpdoChannel : public PdoChannel {
 public:
  static constexpr uint16_t kEmcyLengthShort = 0x8210;  ///< PDO not processed: too few bytes
  static constexpr uint16_t kEmcyLengthLong = 0x8220;   ///< PDO longer than its mapping
  static constexpr uint16_t kEmcyTimeout = 0x8250;      ///< RPDO deadline (event timer) missed

  /// Gives the channel its communication object, before anything else is asked of it.
  void bind(uint16_t communicationIndex) noexcept {
    index_ = communicationIndex;
    deadline_ = kNever;
  }
  /// The TPDO (its channel in PdoContext::tpdos) that answers each PDO this channel accepts
  /// (PdoProfile::tpdoAnswersRpdo). Set once, before configure().
  void answerWith(size_t tpdoChannel) noexcept { answer_ = static_cast<uint8_t>(tpdoChannel + 1U); }
  /// A TPDO answers it (only a quirk profile has them: without, the tests fold away).
  bool answered() const noexcept { return features::kQuirkProfiles && answer_ != 0U; }

  /// Reads the communication parameters and resolves the mapping; drops held data and clears
  /// the EMCY conditions (0x8210, 0x8220, 0x8250) the old parameters raised. The abort code
  /// of a mapping that could not be resolved (the PDO then carries nothing), else kNone.
  /// O(entries x log objects).
  AbortCode configure(PdoContext& context) noexcept;
  /// Resolves the mapping again (a hook was attached). Same result as configure().
  AbortCode resolveMapping(PdoContext& context) noexcept {
    const AbortCode resolved = resolvePdoMapping(context, index_, &map_);
    updateQuietDlc();
    return resolved;
  }

  size_t mappedBytes() const noexcept { return map_.bytes(); }

  /// True for a data frame on this PDO's CAN-ID.
  bool accepts(const CanFrame& frame) const noexcept {
    return valid_ && !frame.rtr && !frame.extended && frame.id == canId_;
  }

  /// A received PDO (node operational). Too few bytes: EMCY 0x8210, nothing applied. More bytes
  /// than mapped: the mapped bytes are applied and EMCY 0x8220 is raised (cleared by the next
  /// PDO of the right length). Types 0..240 hold the data until the next SYNC (discarded after
  /// the SYNC window, 0x1007); 254/255 apply it at once. False when an entry was refused
  /// (nothing written).
  COSTA_HOT_INLINE bool onFrame(PdoContext& context, const CanFrame& frame,
                                Microseconds now) noexcept {
    // The quiet DLC skips checkLength() where speed counts (for size: every frame takes it).
    if ((!kExpandFastPaths || frame.dlc != quietDlc_) && !checkLength(context, frame.dlc)) {
      return true;
    }
    if (eventTimerMs_ != 0U) {
      restartDeadline(context, now);
    }
    if (type_ >= 254U) {
      return apply(context, frame.data);
    }
    if (type_ <= 240U && !reached(now, context.syncWindowEnd)) {
      copyBytes(held_, frame.data, sizeof(held_));
      holding_ = true;
    }
    return true;
  }
  /// An answer signalled for a PDO that an entry then refused is taken back (the refusal is
  /// rare and cold; the answer is signalled before the entries are written, see checkLength()),
  /// unless the TPDO's event was pending already (the application's, or its event timer's).
  void withdrawAnswer(PdoContext& context) const noexcept {
    // cppcheck-suppress knownConditionTrueFalse ; false in a build without quirk profiles
    if (answered() && answerSignalled_) {
      takeBackAnswer(context);
    }
  }
  /// Applies the data held since the previous SYNC. False when an entry was refused.
  bool onSync(PdoContext& context) noexcept {
    if (!holding_) {
      return true;
    }
    holding_ = false;
    return apply(context, held_);
  }
  bool holding() const noexcept { return holding_; }
  /// Deadline monitoring with the event timer (sub-index 5): EMCY 0x8250 when no PDO arrived
  /// within it after the first one.
  void process(PdoContext& context, Microseconds now) noexcept;
  Microseconds nextDeadline() const noexcept { return deadline_; }
  /// Leaving operational: held data and monitoring stop. A missed deadline stays an error
  /// (EMCY 0x8250) until a PDO arrives or the PDO is configured again.
  void stop() noexcept {
    holding_ = false;
    deadline_ = kNever;
  }

 private:
  /// Writes `data` into the mapped entries, with the listeners' notifications around it. A plain
  /// mapping is expanded here where speed counts; built for size, every RPDO takes
  /// applyChecked(), which then checks only the entries that need it.
  COSTA_HOT_INLINE bool apply(PdoContext& context, const uint8_t* data) noexcept {
    if (!kExpandFastPaths || !map_.plain()) {
      return applyChecked(context, data);
    }
    notifyWriting(context);
    map_.write(context.access, data);
    notifyReceived(context);
    return true;
  }
  bool applyChecked(PdoContext& context, const uint8_t* data) noexcept;
  void notifyWriting(PdoContext& context) const noexcept {
    const uint16_t index = index_;
    context.listeners.notify([index](NodeEvents& listener) { listener.onRpdoWriting(index); });
  }
  void notifyReceived(PdoContext& context) const noexcept {
    const uint16_t index = index_;
    context.listeners.notify([index](NodeEvents& listener) { listener.onRpdoReceived(index); });
  }
  void takeBackAnswer(PdoContext& context) const noexcept;
  void restartDeadline(PdoContext& context, Microseconds now) noexcept;
  /// The EMCY conditions a PDO raises, one bit each of raised_.
  enum Condition : uint8_t { kTooShort = 1, kTooLong = 2, kTimedOut = 4 };
  /// Raises the condition's EMCY (`on`), or clears it when this PDO raised it.
  void setCondition(PdoContext& context, Condition condition, bool on) noexcept;
  bool raised(Condition condition) const noexcept { return (raised_ & condition) != 0U; }
  void updateQuietDlc() noexcept;
  /// Raises or clears EMCY 0x8210/0x8220 for a frame of `dlc` bytes; looks nothing up while
  /// the length stays right. False for a frame too short to apply. A frame that will be taken
  /// signals the answering TPDO (all frames come here when there is one: quietDlc_).
  bool checkLength(PdoContext& context, uint8_t dlc) noexcept;
  uint8_t source() const noexcept { return static_cast<uint8_t>(index_ & 0xFFU); }

  bool holding_ = false;
  uint8_t raised_ = 0;  ///< the Condition bits whose EMCY this PDO raised
  /// The DLC for which onFrame() takes the quiet path: the mapped bytes while neither length
  /// EMCY is raised and no TPDO answers, else none (0xFF).
  uint8_t quietDlc_ = 0;
  /// The TPDO that answers every PDO taken (PdoProfile::tpdoAnswersRpdo): its channel in
  /// PdoContext::tpdos plus 1, or 0 for none (a byte, so that the channel keeps its size).
  uint8_t answer_ = 0;
  /// The answer of the PDO being taken raised its TPDO's event (none was pending already).
  bool answerSignalled_ = false;
  /// kNever from bind() on (set there, so that an array of channels is all zeros at first), and
  /// while the deadline is missed (kTimedOut) or not monitored.
  Microseconds deadline_ = 0;
  PdoMap map_;
  uint8_t held_[PdoMap::kMaxBytes] = {};
};

}  // namespace costa
