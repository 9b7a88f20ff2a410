#include "fuzz_session.hpp"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <map>
#include <memory>
#include <optional>

#include "checked_state.hpp"
#include "costa/cob_ids.hpp"
#include "costa/port/memory/recording_can.hpp"
#include "dictionary_rules.hpp"
#include "frame_rules.hpp"
#include "fuzzed_device.hpp"
#include "state_rules.hpp"
#include "storage_rules.hpp"
#include "watching_can.hpp"

namespace costa::fuzz {
namespace {

/// Immediate deadlines (equal to now) tolerated in a row, as the in-process test bus does.
constexpr int kImmediateRunsAllowed = 1000;
/// process() calls an input may make; it ends early after the event that reaches them, so that
/// every input runs in bounded time: 10 s of a 1 ms timer (long waits with one would take
/// minutes, and a few such inputs used to take most of the fuzzer's time).
constexpr uint64_t kProcessCallBudget = 10000;
/// Recorded frames are checked early when this many wait (a long wait with a fast heartbeat).
constexpr size_t kFramesBeforeCheck = port::RecordingCan::kCapacity / 2U;

/// The command of a kSimulate event, up to its first NUL (control() takes a C string).
std::string commandOf(const Event& event) {
  const std::string text(reinterpret_cast<const char*>(event.text), event.textLength);
  return text.substr(0, text.find('\0'));
}

/// `text` with every byte outside printable ASCII as \xNN (for traces).
std::string printable(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20U && byte < 0x7FU && byte != '\\') {
      out += c;
    } else {
      char escaped[8];
      snprintf(escaped, sizeof(escaped), "\\x%02X", static_cast<unsigned>(byte));
      out += escaped;
    }
  }
  return out;
}

std::string describe(const Event& event) {
  switch (event.kind) {
    case EventKind::kFrame: return "rx " + describeFrame(event.frame);
    case EventKind::kOwnSdoRequest: return "own SDO rx 6xx " + describeFrame(event.frame).substr(4);
    case EventKind::kWait: return "wait " + std::to_string(event.duration) + " us";
    case EventKind::kWaitForDeadline:
      return event.duration == 0U ? "wait for the deadline" : "wait until 1 us before it";
    case EventKind::kRefuseFrames: return "controller refuses frames";
    case EventKind::kAcceptFrames: return "controller takes frames";
    case EventKind::kControllerEvent: return "controller event " + std::to_string(event.code);
    case EventKind::kPowerCycle: return "power cycle";
    case EventKind::kStoragePowerCut:
      return "storage power cut after " + std::to_string(event.bytes) + " bytes";
    case EventKind::kSimulate: return "sim " + printable(commandOf(event));
    case EventKind::kEntryUpload: return "upload of entry " + std::to_string(event.code);
    case EventKind::kEntryDownload: return "download to entry " + std::to_string(event.code);
    case EventKind::kNothing: break;
  }
  return "nothing";
}

/// A device of the list with its controller, made once per device and program and renewed
/// for every input (the same memory for every input: no allocation per input).
struct Bench {
  WatchingCan can;
  std::unique_ptr<FuzzedDevice> device;
};

Bench* benchFor(const std::string& device) {
  static std::map<std::string, std::unique_ptr<Bench>> benches;
  std::unique_ptr<Bench>& bench = benches[device];
  if (!bench) {
    bench = std::make_unique<Bench>();
    bench->device = createFuzzedDevice(device, bench->can, PowerOnOptions{});
    if (!bench->device) {
      benches.erase(device);
      return nullptr;
    }
  }
  return bench.get();
}

class Session {
 public:
  Session(Bench* bench, const PowerOnOptions& options, std::string* trace)
      : can_(bench->can), device_(bench->device.get()), trace_(trace) {
    device_->renew(options);
    can_.watch(device_);
  }

  /// The input has used up its process() calls: it ends here.
  bool exhausted() const { return processCalls_ >= kProcessCallBudget; }

  std::string powerOn() {
    can_.setAccepting(true);
    indicators_.reset();  // it listens to the node the power-on replaces
    leds_.run = false;
    leds_.error = false;
    const size_t storageCalls = device_->storage().modifyingCalls();
    device_->powerOn(now_);
    indicators_.emplace(device_->node(), leds_);
    std::string problem = runProcess();
    freshFromPowerOn_ = device_->storage().modifyingCalls() == storageCalls;
    return problem;
  }

  /// Applies one event, then checks every invariant.
  std::string apply(const Event& event) {
    std::string problem = perform(event);
    if (problem.empty()) {
      problem = checkAll();
    }
    if (problem.empty() && !device_->storage().powered()) {
      // The power failed during a write to the storage: the device restarts.
      problem = powerOn();
      if (problem.empty()) {
        problem = checkAll();
      }
    }
    return problem;
  }

  /// Every invariant, after power-on or an event.
  std::string checkAll() {
    Node& node = device_->node();
    const bool unchanged = checked_.same(node);
    const CanIdSet allowedNow =
        unchanged ? checked_.allowed() : allowedTransmitIds(node, device_->hasLss());
    std::string problem = checkFrames(allowedNow);
    if (problem.empty() && !unchanged) {
      problem = checkDictionaryValues(node.dictionary());
    }
    if (problem.empty() && !unchanged) {
      problem = checkConfiguredCanIds(node);
    }
    if (problem.empty() && !unchanged) {
      checked_.remember(node, allowedNow);
    }
    if (problem.empty()) {
      problem = checkStateMachines(node, device_->hasLss());
    }
    if (problem.empty()) {
      problem = device_->checkDevice();
    }
    if (problem.empty() && indicators_) {
      (void)indicators_->process(now_);
      problem = checkIndicators(node, *indicators_, leds_.run, leds_.error);
    }
    port::MemoryStorage& storage = device_->storage();
    if (problem.empty() && storage.modifyingCalls() != storageChanges_) {
      storageChanges_ = storage.modifyingCalls();
      problem = checkStoredParameters(node.dictionary().definition(), node.nodeId(), storage);
    }
    // A frame may wait in the node's queue while the controller refuses frames, and leave after
    // its node-id or COB-ID changed: it may use any id allowed since the queue was last empty.
    if (node.txPending()) {
      allowedBefore_.merge(allowedNow);
    } else {
      allowedBefore_ = allowedNow;
    }
    return problem;
  }

  Microseconds now() const { return now_; }

 private:
  std::string perform(const Event& event) {
    Node& node = device_->node();
    if (event.kind != EventKind::kPowerCycle && event.kind != EventKind::kStoragePowerCut &&
        event.kind != EventKind::kNothing) {
      freshFromPowerOn_ = false;
    }
    switch (event.kind) {
      case EventKind::kFrame: device_->onFrame(event.frame, now_); return runProcess();
      case EventKind::kOwnSdoRequest: {
        CanFrame frame = event.frame;
        frame.id = cob::kSdoRxBase + node.nodeId();
        device_->onFrame(frame, now_);
        return runProcess();
      }
      case EventKind::kWait: return advanceTo(now_ + event.duration);
      case EventKind::kWaitForDeadline:
        if (next_ != kNever && before(now_, next_ - event.duration)) {
          return advanceTo(next_ - event.duration);
        }
        return "";
      case EventKind::kRefuseFrames: can_.setAccepting(false); return "";
      case EventKind::kAcceptFrames:
        can_.setAccepting(true);
        node.flushTx();
        return runProcess();
      case EventKind::kControllerEvent:
        node.onControllerEvent(static_cast<CanControllerEvent>(event.code), now_);
        return runProcess();
      case EventKind::kPowerCycle: return freshFromPowerOn_ ? repeatedPowerOn() : powerOn();
      case EventKind::kStoragePowerCut: device_->storage().cutPowerAfter(event.bytes); return "";
      case EventKind::kSimulate: {
        const std::string refused = device_->control(commandOf(event).c_str());
        if (trace_ != nullptr && !refused.empty()) {
          *trace_ += "  = refused: " + refused + "\n";
        }
        return runProcess();
      }
      case EventKind::kEntryUpload:
      case EventKind::kEntryDownload: return sdoToEntry(event);
      case EventKind::kNothing: break;
    }
    return "";
  }

  /// A power cycle right after a power-on that left the medium as it was, with no event since
  /// but storage power cuts: the same composition would start from the same medium at the same
  /// time and do the same, so it is not built again (most power cycles of a grown corpus come
  /// in such runs). As a power cycle does, it disarms a pending power cut.
  std::string repeatedPowerOn() {
    device_->storage().restorePower();
    if (trace_ != nullptr) {
      *trace_ += "  = the same as the power-on before it: not repeated\n";
    }
    return "";
  }

  /// An SDO request of entry event.code (modulo the number of entries), to the own server.
  std::string sdoToEntry(const Event& event) {
    const od::Definition& definition = device_->node().dictionary().definition();
    size_t entries = 0;
    for (size_t i = 0; i < definition.objectCount; ++i) {
      entries += od::entryCount(definition, definition.objects[i]);
    }
    size_t wanted = event.code % entries;
    od::EntryRef entry;
    for (const od::EntryRef& ref : od::Entries(definition)) {
      if (wanted-- == 0U) {
        entry = ref;
        break;
      }
    }
    CanFrame frame;
    frame.id = cob::kSdoRxBase + device_->node().nodeId();
    frame.dlc = 8;
    if (event.kind == EventKind::kEntryUpload) {
      frame.data[0] = 0x40;  // initiate upload
    } else {
      const size_t size = entry.size() >= 1U && entry.size() <= 4U ? entry.size() : 4U;
      frame.data[0] = static_cast<uint8_t>(0x23U | ((4U - size) << 2U));  // expedited, sized
      memcpy(frame.data + 4, event.frame.data, size);
    }
    frame.data[1] = static_cast<uint8_t>(entry.index());
    frame.data[2] = static_cast<uint8_t>(entry.index() >> 8U);
    frame.data[3] = entry.subIndex();
    if (trace_ != nullptr) {
      *trace_ += "  = rx " + describeFrame(frame) + "\n";
    }
    device_->onFrame(frame, now_);
    return runProcess();
  }

  /// Calls process() now, again while it asks for an immediate call.
  std::string runProcess() {
    for (int run = 0;; ++run) {
      next_ = device_->process(now_);
      ++processCalls_;
      if (can_.count() > kFramesBeforeCheck) {
        const std::string problem =
            checkFrames(allowedTransmitIds(device_->node(), device_->hasLss()));
        if (!problem.empty()) {
          return problem;
        }
      }
      if (next_ == kNever || before(now_, next_)) {
        return "";
      }
      if (next_ != atOnce(now_)) {
        return "process() at " + std::to_string(now_) + " us asked to run again at " +
               std::to_string(next_) + " us, in the past";
      }
      if (run == kImmediateRunsAllowed) {
        return "process() at " + std::to_string(now_) + " us asked for an immediate call " +
               std::to_string(kImmediateRunsAllowed) + " times in a row";
      }
    }
  }

  /// Advances the clock to `end`, running process() at every deadline on the way.
  std::string advanceTo(Microseconds end) {
    while (next_ != kNever && !before(end, next_)) {
      if (exhausted()) {
        return "";  // the input ends after this event
      }
      if (before(now_, next_)) {
        now_ = next_;
      }
      const std::string problem = runProcess();
      if (!problem.empty()) {
        return problem;
      }
    }
    now_ = end;
    return runProcess();
  }

  /// Checks the frames sent since the last check against the ids allowed now (`allowedNow`),
  /// before the event, and since the transmit queue was last empty; forgets them.
  std::string checkFrames(const CanIdSet& allowedNow) {
    if (!can_.problem().empty()) {
      return can_.problem();
    }
    if (can_.count() == 0U) {
      return "";
    }
    const Node& node = device_->node();
    CanIdSet allowed = allowedNow;
    allowed.merge(allowedBefore_);
    for (size_t i = 0; i < can_.count(); ++i) {
      if (trace_ != nullptr) {
        *trace_ += "  tx " + describeFrame(can_.at(i)) + "\n";
      }
      const std::string problem = checkTransmittedFrame(can_.at(i), allowed);
      if (!problem.empty()) {
        return problem + " (node-id " + std::to_string(node.nodeId()) + ")";
      }
    }
    can_.clear();
    return "";
  }

  /// The two LEDs of the node's CiA 303-3 indicators, as the fuzzer sees them.
  class Leds final : public IndicatorOutputs {
   public:
    void setRun(bool on) noexcept override { run = on; }
    void setError(bool on) noexcept override { error = on; }
    bool run = false;
    bool error = false;
  };

  WatchingCan& can_;
  FuzzedDevice* device_;
  Leds leds_;
  std::optional<Indicators> indicators_;  ///< over the node of the latest power-on
  std::string* trace_;
  /// One second before the 32-bit clock wraps, as the transcript replays: inputs cross the wrap.
  Microseconds now_ = 0xFFFFFFFFU - 999999U;
  Microseconds next_ = kNever;
  CanIdSet allowedBefore_;  ///< at the end of the last event, and while frames were queued
  CheckedState checked_;    ///< what the dictionary and CAN-ID checks last passed on
  /// Modifying calls to the medium when its contents were last checked. renew() leaves it erased
  /// (nothing stored: every group loads as no image) with its counters at 0, so the first check
  /// is that of the first call that modifies it.
  size_t storageChanges_ = 0;
  uint64_t processCalls_ = 0;
  /// The node is as a power-on that left the medium unchanged made it: no event came since, or
  /// only storage power cuts (which a power cycle disarms) and events that do nothing.
  bool freshFromPowerOn_ = false;
};

}  // namespace

std::string runFuzzInput(const std::string& device, const uint8_t* data, size_t size,
                         std::string* trace) {
  EventReader reader(data, size);
  const PowerOnOptions options = decodeHeader(reader.header());
  Bench* bench = benchFor(device);
  if (bench == nullptr) {
    return "unknown device '" + device + "'";
  }
  auto session = std::make_unique<Session>(bench, options, trace);
  if (trace != nullptr) {
    *trace += "power-on, node-id " + std::to_string(options.nodeId) +
              (options.explicitId ? " (explicit)\n" : " (the device's own)\n");
  }
  std::string problem = session->powerOn();
  if (problem.empty()) {
    problem = session->checkAll();
  }
  if (!problem.empty()) {
    return "power-on: " + problem;
  }
  Event event;
  for (size_t count = 1; !session->exhausted() && reader.next(&event); ++count) {
    if (trace != nullptr) {
      *trace += std::to_string(session->now()) + " us: event " + std::to_string(count) + " " +
                describe(event) + "\n";
    }
    problem = session->apply(event);
    if (!problem.empty()) {
      return "event " + std::to_string(count) + " (" + describe(event) + ") at " +
             std::to_string(session->now()) + " us: " + problem;
    }
  }
  return "";
}

}  // namespace costa::fuzz
