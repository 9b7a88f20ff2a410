#include "costa/emcy_producer.hpp"

#include "costa/cob_ids.hpp"
#include "costa/od/bytes.hpp"
#include "costa/od/little_endian.hpp"

namespace costa {
namespace {

/// The sub-indices of the error history 0x1003, sub-index 0 included; 0 without the object.
unsigned historyEntries(const od::ObjectDictionary& dictionary) noexcept {
  const od::Object* history = dictionary.findObject(EmcyProducer::kErrorHistoryIndex);
  return history == nullptr ? 0U : dictionary.entryCount(*history);
}

}  // namespace

uint8_t errorRegisterBitFor(uint16_t code) noexcept {
  switch (code >> 12U) {
    case 0x2: return kErrorCurrent;
    case 0x3: return kErrorVoltage;
    case 0x4: return kErrorTemperature;
    case 0x8:  // monitoring: communication (0x81xx) and protocol errors (0x82xx) only
      return (code >> 8U) == 0x81U || (code >> 8U) == 0x82U ? uint8_t{kErrorCommunication}
                                                            : uint8_t{0};
    case 0xF: return kErrorManufacturer;
    default: return 0;
  }
}

void EmcyProducer::onResetCommunication() noexcept {
  pendingHead_ = 0;
  pendingCount_ = 0;
  nextAllowed_ = kNever;
  publishRegister();
}

uint8_t EmcyProducer::frameRegister(uint8_t registerBits) const noexcept {
  if (!profile_.reportErrorRegister) {
    return 0;
  }
  auto value = static_cast<uint8_t>(kErrorGeneric | registerBits);
  for (size_t i = 0; i < count_; ++i) {
    value = static_cast<uint8_t>(value | conditions_[i].registerBits);
  }
  return value;
}

size_t EmcyProducer::position(uint16_t code, uint8_t source) const noexcept {
  size_t i = 0;
  while (i < count_ && (conditions_[i].code != code || conditions_[i].source != source)) {
    ++i;
  }
  return i;
}

bool EmcyProducer::raise(uint16_t code, uint8_t source, uint8_t registerBits,
                         const uint8_t* manufacturer) noexcept {
  if (active(code, source)) {
    return false;
  }
  const bool stored = count_ < capacity_;
  if (stored) {
    conditions_[count_++] = EmcyCondition{code, source, registerBits};
  } else {
    ++conditionsFull_;
  }
  publishRegister();
  record(code, manufacturer);
  enqueue(code, frameRegister(registerBits), manufacturer);
  return stored;
}

bool EmcyProducer::clear(uint16_t code, uint8_t source) noexcept {
  const size_t i = position(code, source);
  if (i == count_) {
    return false;
  }
  conditions_[i] = conditions_[--count_];  // the last takes its place
  publishRegister();
  if (count_ == 0U && profile_.errorResetFrame) {
    enqueue(0x0000, 0, nullptr);
  }
  return true;
}

void EmcyProducer::signal(uint16_t code, uint8_t registerBits,
                          const uint8_t* manufacturer) noexcept {
  record(code, manufacturer);
  enqueue(code, frameRegister(registerBits), manufacturer);
}

void EmcyProducer::publishRegister() noexcept {
  dictionary_.storeUnsigned32(kErrorRegisterIndex, 0, errorRegister());  // when 0x1001 is there
}

void EmcyProducer::record(uint16_t code, const uint8_t* manufacturer) noexcept {
  const unsigned entries = historyEntries(dictionary_);
  if (entries < 2U) {
    return;  // no history, or one without room for an error
  }
  const auto capacity = static_cast<uint8_t>(entries - 1U);
  auto count = static_cast<uint8_t>(dictionary_.readUnsigned32(kErrorHistoryIndex, 0, 0));
  if (count < capacity) {
    ++count;
  }
  uint32_t info = 0;
  if (manufacturer != nullptr) {
    info = static_cast<uint32_t>(manufacturer[0]) | (static_cast<uint32_t>(manufacturer[1]) << 8U);
  }
  // The newest error into sub-index 1, each older one a sub-index up (the oldest of a full
  // history drops out): one pass that carries each value to the next sub-index.
  uint32_t value = code | (info << 16U);
  for (unsigned sub = 1; sub <= count; ++sub) {
    const uint32_t older =
        dictionary_.readUnsigned32(kErrorHistoryIndex, static_cast<uint8_t>(sub), 0);
    dictionary_.storeUnsigned32(kErrorHistoryIndex, static_cast<uint8_t>(sub), value);
    value = older;
  }
  dictionary_.storeUnsigned32(kErrorHistoryIndex, 0, count);
}

void EmcyProducer::enqueue(uint16_t code, uint8_t registerValue,
                           const uint8_t* manufacturer) noexcept {
  if (!profile_.sendFrames) {
    return;  // a device without EMCY: the register and the history only
  }
  if (pendingCount_ == pendingCapacity_) {
    ++lost_;
    return;
  }
  size_t tail = pendingHead_ + pendingCount_;
  if (tail >= pendingCapacity_) {
    tail -= pendingCapacity_;
  }
  PendingEmcy& slot = pending_[tail];
  slot = PendingEmcy{};
  if (profile_.layout == EmcyLayout::kErrorRegisterInFourthByte) {
    slot.data[3] = registerValue;
  } else {
    storeU16(slot.data, code);
    slot.data[2] = registerValue;
    if (manufacturer != nullptr) {
      copyBytes(&slot.data[3], manufacturer, 5);
    }
  }
  ++pendingCount_;
  clock_.schedule(nextAllowed_ == kNever ? atOnce(clock_.now) : nextAllowed_);
}

uint32_t EmcyProducer::cobId() const noexcept {
  return dictionary_.readUnsigned32(kCobIdIndex, 0, cob::kEmcyBase + nodeId_);
}

void EmcyProducer::process(Microseconds now, NmtState state, TransmitPath& tx) noexcept {
  if (nextAllowed_ != kNever) {
    if (!reached(now, nextAllowed_)) {
      return;  // within the inhibit time
    }
    nextAllowed_ = kNever;  // the inhibit time is over
  }
  if (pendingCount_ == 0U ||
      (state != NmtState::kPreOperational && state != NmtState::kOperational)) {
    return;  // nothing to send now: no lookup of the COB-ID and the inhibit time
  }
  const uint32_t cob = cobId();
  if ((cob & 0x80000000U) != 0U) {
    pendingCount_ = 0;  // EMCY not valid: nothing is produced
    return;
  }
  const auto inhibit = dictionary_.readUnsigned32(kInhibitIndex, 0, 0) * kHundredMicroseconds;
  // Every queued frame without an inhibit time; one frame, and the inhibit time, with one.
  do {
    tx.send(cob & 0x7FFU, pending_[pendingHead_].data, sizeof(pending_->data));
    pendingHead_ = pendingHead_ + 1U == pendingCapacity_ ? 0U : pendingHead_ + 1U;
    --pendingCount_;
  } while (inhibit == 0U && pendingCount_ != 0U);
  if (inhibit != 0U) {
    nextAllowed_ = at(now, inhibit);
  }
}

Microseconds EmcyProducer::nextDeadline(NmtState state) const noexcept {
  if (nextAllowed_ != kNever) {
    return nextAllowed_;  // the end of the inhibit time: a waiting EMCY leaves, or it expires
  }
  if (pendingCount_ == 0U ||
      (state != NmtState::kPreOperational && state != NmtState::kOperational)) {
    return kNever;
  }
  return atOnce(clock_.now);
}

AbortCode EmcyProducer::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                              const uint8_t* data, size_t length) noexcept {
  if (ref.index() == kErrorHistoryIndex) {
    if (ref.subIndex() == 0U && length != 1U) {
      // Sub-index 0 is an UNSIGNED8: the length is checked before the value (CiA 301).
      return length > 1U ? AbortCode::kLengthTooHigh : AbortCode::kLengthTooLow;
    }
    if (ref.subIndex() != 0U || data[0] != 0U) {
      return AbortCode::kInvalidValue;
    }
    // Every sub-index to 0, the last first: one loop ends with sub-index 0, the count.
    for (unsigned sub = historyEntries(dictionary); sub-- != 0U;) {
      dictionary.storeUnsigned32(kErrorHistoryIndex, static_cast<uint8_t>(sub), 0);
    }
    return AbortCode::kNone;
  }
  if (ref.index() == kCobIdIndex && length == 4U) {
    const auto value = static_cast<uint32_t>(loadLittleEndian(data, length));
    const uint32_t current = cobId();
    const bool wasValid = (current & 0x80000000U) == 0U;
    const bool willBeValid = (value & 0x80000000U) == 0U;
    if (!cob::acceptableCobId(value, willBeValid, wasValid && willBeValid, current & 0x7FFU)) {
      return AbortCode::kInvalidValue;
    }
  }
  return dictionary.write(ref, data, length);
}

}  // namespace costa
