#include "costa/safety_service.hpp"

#include "costa/emcy_producer.hpp"
#include "costa/nmt_state_machine.hpp"
#include "costa/node_events.hpp"
#include "costa/object_access.hpp"

namespace costa {
namespace {

constexpr uint8_t kCommunicationErrorBit = 0x10;

/// One mapped pair of an SRDO: the normal entry, and the inverted entry when it is one of its own
/// (CiA 304: the application's inverted copy) of the same size; `copy` is not valid when the
/// pair names the normal entry twice (the stack inverts it). `normal` is not valid: no pair.
struct MappedPair {
  od::EntryRef normal;
  od::EntryRef copy;
};

od::EntryRef entryOf(const od::ObjectDictionary& dictionary, uint32_t mapping) noexcept {
  return dictionary.find(static_cast<uint16_t>(mapping >> 16U),
                         static_cast<uint8_t>(mapping >> 8U));
}

/// The pair at odd sub-index `sub` of SRDO mapping object `mapping`.
MappedPair mappedPair(const od::ObjectDictionary& dictionary, uint16_t mapping,
                      uint8_t sub) noexcept {
  const uint32_t normal = dictionary.readUnsigned32(mapping, sub, 0);
  const uint32_t inverted = dictionary.readUnsigned32(mapping, sub + 1U, 0);
  MappedPair pair{entryOf(dictionary, normal), {}};
  if (inverted != normal) {
    const od::EntryRef copy = entryOf(dictionary, inverted);
    if (copy.valid() && pair.normal.valid() && copy.size() == pair.normal.size()) {
      pair.copy = copy;
    }
  }
  return pair;
}

/// EMCY error code of a failure: CiA 301's closest, CiA 304 names none (docs/manual-errata.md,
/// "SRDO failures and the safe state").
uint16_t emcyCode(SrdoFailure failure) noexcept {
  switch (failure) {
    case SrdoFailure::kCycleTime:
    case SrdoFailure::kValidationTime: return 0x8250;
    case SrdoFailure::kLength: return 0x8210;
    case SrdoFailure::kNotInverted:
    case SrdoFailure::kSequence: return 0x8200;
    default: return 0x6300;
  }
}

bool srdoObject(uint16_t index) noexcept {
  return index >= srdo::kFirstCommunication && index <= srdo::kSignatures;
}

}  // namespace

bool SafetyService::gfcValid() const noexcept {
  return s_.access.dictionary().readUnsigned32(kGfcIndex, 0, 0) == 1U;
}

bool SafetyService::operational() const noexcept {
  return s_.nmt.state() == NmtState::kOperational;
}

bool SafetyService::workingStateAllowed() const noexcept {
  return operational() && running_ && !safe_;
}

void SafetyService::addRoutes(FrameRouter& router) const noexcept {
  if (gfcValid()) {
    (void)router.add(kGfcCanId, Route::kGfc);
  }
  const od::ObjectDictionary& dictionary = s_.access.dictionary();
  for (uint8_t slot = 0; slot < s_.channelCount; ++slot) {
    const auto index = static_cast<uint16_t>(srdo::kFirstCommunication + slot);
    if (dictionary.readUnsigned32(index, 1, 0) != srdo::kReceive) {
      continue;
    }
    const auto normal = dictionary.readUnsigned32(index, 5, 0);
    const auto inverted = dictionary.readUnsigned32(index, 6, 0);
    if (normal <= FrameRouter::kLargestId && inverted <= FrameRouter::kLargestId) {
      (void)router.add(static_cast<uint16_t>(normal), Route::kSrdo,
                       static_cast<uint8_t>(2U * slot));
      (void)router.add(static_cast<uint16_t>(inverted), Route::kSrdo,
                       static_cast<uint8_t>(2U * slot + 1U));
    }
  }
}

bool SafetyService::onGfc(const CanFrame& frame) noexcept {
  if (frame.rtr || frame.dlc != 0U) {
    return false;
  }
  s_.listeners.notify([](NodeEvents& listener) { listener.onGlobalFailSafe(); });
  if (operational() && started_ && !safe_) {
    stop();
    safe_ = true;
    s_.listeners.notify(
        [](NodeEvents& listener) { listener.onSafeState(0, SrdoFailure::kGlobalFailSafe); });
  }
  return true;
}

bool SafetyService::sendGfc(bool allowed) noexcept {
  if (!allowed || !gfcValid()) {
    return false;
  }
  CanFrame frame;
  frame.id = kGfcCanId;
  frame.dlc = 0;
  s_.tx.send(frame);
  return true;
}

void SafetyService::start(Microseconds now) noexcept {
  started_ = true;
  safe_ = false;
  active_ = 0;
  const od::ObjectDictionary& dictionary = s_.access.dictionary();
  const bool anySrdo = dictionary.findObject(srdo::kConfigurationValid) != nullptr;
  if (anySrdo && dictionary.readUnsigned32(srdo::kConfigurationValid, 0, 0) != srdo::kValid) {
    return;  // not configured: no SRDO runs, the working state is not allowed
  }
  for (uint8_t number = 1; number <= 64U; ++number) {
    const auto index = static_cast<uint16_t>(srdo::kFirstCommunication + number - 1U);
    if (dictionary.findObject(index) == nullptr) {
      continue;
    }
    SrdoConfiguration configuration;
    const SrdoCheck check = readSrdoConfiguration(dictionary, number, &configuration);
    if (check == SrdoCheck::kNotValid) {
      continue;
    }
    if (check != SrdoCheck::kValid || number > s_.channelCount) {
      fail(SrdoFailure::kSignature, number);
      return;
    }
    s_.channels[number - 1U].start(configuration, now);
    active_ = number;
  }
  running_ = true;
}

void SafetyService::stop() noexcept {
  running_ = false;
  for (uint8_t slot = 0; slot < s_.channelCount; ++slot) {
    s_.channels[slot].stop();
  }
}

void SafetyService::fail(SrdoFailure failure, uint8_t number) noexcept {
  if (safe_) {
    return;
  }
  stop();
  safe_ = true;
  const uint8_t manufacturer[5] = {static_cast<uint8_t>(failure), number, 0, 0, 0};
  s_.emcy.signal(emcyCode(failure), kCommunicationErrorBit, manufacturer);
  s_.listeners.notify(
      [failure, number](NodeEvents& listener) { listener.onSafeState(number, failure); });
}

bool SafetyService::unchanged(const SrdoChannel& channel) const noexcept {
  const od::ObjectDictionary& dictionary = s_.access.dictionary();
  SrdoConfiguration now;
  return dictionary.readUnsigned32(srdo::kConfigurationValid, 0, 0) == srdo::kValid &&
         readSrdoConfiguration(dictionary, channel.configuration().number, &now) ==
             SrdoCheck::kValid &&
         now.signature == channel.configuration().signature;
}

void SafetyService::transmit(const SrdoChannel& channel) noexcept {
  const SrdoConfiguration& c = channel.configuration();
  const od::ObjectDictionary& dictionary = s_.access.dictionary();
  const auto mapping = static_cast<uint16_t>(srdo::kFirstMapping + c.number - 1U);
  CanFrame normal;
  normal.id = c.normalId;
  normal.dlc = c.length;
  CanFrame inverted;
  inverted.id = c.invertedId;
  inverted.dlc = c.length;
  size_t offset = 0;
  for (uint8_t sub = 1; sub < c.mappedCount; sub = static_cast<uint8_t>(sub + 2U)) {
    const MappedPair pair = mappedPair(dictionary, mapping, sub);
    if (!pair.normal.valid() || offset + pair.normal.size() > sizeof(normal.data)) {
      continue;  // not after checkSrdoMapping() (the configuration is checked every cycle)
    }
    const size_t size = dictionary.read(pair.normal, 0, normal.data + offset, pair.normal.size());
    if (pair.copy.valid()) {
      (void)dictionary.read(pair.copy, 0, inverted.data + offset,
                            size);  // as the application keeps it
    } else {
      for (size_t i = offset; i < offset + size; ++i) {
        inverted.data[i] = static_cast<uint8_t>(~normal.data[i]);
      }
    }
    offset += size;
  }
  s_.tx.send(normal);
  s_.tx.send(inverted);
}

void SafetyService::deliver(const SrdoChannel& channel) noexcept {
  const SrdoConfiguration& c = channel.configuration();
  od::ObjectDictionary& dictionary = s_.access.dictionary();
  const auto mapping = static_cast<uint16_t>(srdo::kFirstMapping + c.number - 1U);
  size_t offset = 0;
  for (uint8_t sub = 1; sub < c.mappedCount; sub = static_cast<uint8_t>(sub + 2U)) {
    const MappedPair pair = mappedPair(dictionary, mapping, sub);
    if (!pair.normal.valid() || offset + pair.normal.size() > c.length) {
      continue;
    }
    const size_t size = pair.normal.size();
    (void)s_.access.write(pair.normal, channel.data() + offset, size);
    if (pair.copy.valid()) {
      // The inverted frame was checked to be the NOT of the normal one: its bytes, for the
      // application's inverted copy.
      uint8_t bytes[8] = {};
      for (size_t i = 0; i < size; ++i) {
        bytes[i] = static_cast<uint8_t>(~channel.data()[offset + i]);
      }
      (void)s_.access.write(pair.copy, bytes, size);
    }
    offset += size;
  }
}

bool SafetyService::onSrdo(const CanFrame& frame, uint8_t channel, Microseconds now) noexcept {
  if (!operational()) {
    return false;
  }
  if (!started_) {
    start(now);
  }
  const auto slot = static_cast<uint8_t>(channel / 2U);
  if (slot >= s_.channelCount) {
    return false;
  }
  SrdoChannel& srdo = s_.channels[slot];
  if (!srdo.running()) {
    return false;
  }
  bool complete = false;
  const SrdoFailure failure = srdo.onFrame(frame, (channel & 1U) != 0U, now, &complete);
  s_.clock.schedule(srdo.nextDeadline());
  if (failure != SrdoFailure::kNone) {
    fail(failure, srdo.configuration().number);
  } else if (complete) {
    if (unchanged(srdo)) {
      deliver(srdo);
    } else {
      fail(SrdoFailure::kConfigurationChanged, srdo.configuration().number);
    }
  }
  return true;
}

void SafetyService::process(Microseconds now) noexcept {
  if (!operational()) {
    if (started_) {
      started_ = false;
      safe_ = false;
      stop();
    }
    return;
  }
  if (!started_) {
    start(now);
  }
  for (uint8_t slot = 0; running_ && slot < active_; ++slot) {
    SrdoChannel& channel = s_.channels[slot];
    const SrdoFailure late = channel.checkDeadlines(now);
    if (late != SrdoFailure::kNone) {
      fail(late, channel.configuration().number);
    } else if (channel.transmitDue(now)) {
      if (unchanged(channel)) {
        transmit(channel);
      } else {
        fail(SrdoFailure::kConfigurationChanged, channel.configuration().number);
      }
    }
  }
}

Microseconds SafetyService::nextDeadline() const noexcept {
  Microseconds next = kNever;
  for (uint8_t slot = 0; running_ && slot < active_; ++slot) {
    next = earliest(next, s_.channels[slot].nextDeadline());
  }
  return next;
}

AbortCode SafetyService::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                               const uint8_t* data, size_t length) noexcept {
  const uint16_t index = ref.index();
  if (index == kGfcIndex) {
    if (length == 1U && data[0] > 1U) {
      return AbortCode::kInvalidValue;
    }
  } else if (srdoObject(index)) {
    if (operational()) {
      return AbortCode::kCannotStoreState;  // CiA 304: no configuration while operational
    }
    const AbortCode refused = checkSrdoWrite(dictionary, ref, data, length);
    if (refused != AbortCode::kNone) {
      return refused;
    }
  }
  const AbortCode written = dictionary.write(ref, data, length);
  if (written != AbortCode::kNone) {
    return written;
  }
  if (srdoObject(index) && index != srdo::kConfigurationValid) {
    (void)dictionary.storeUnsigned32(srdo::kConfigurationValid, 0, srdo::kNotValid);
  }
  s_.routes.invalidate();
  return AbortCode::kNone;
}

}  // namespace costa
