#include "costa/pdo_engine.hpp"

#include "costa/frame_router.hpp"
#include "costa/od/little_endian.hpp"

namespace costa {
namespace {

constexpr uint16_t kRpdoCommunicationFirst = 0x1400;
constexpr uint16_t kRpdoCommunicationLast = 0x15FF;
constexpr uint16_t kTpdoCommunicationFirst = 0x1800;
constexpr uint16_t kTpdoCommunicationLast = 0x19FF;
constexpr uint16_t kMappingOffset = 0x200;

}  // namespace

void PdoEngine::bind() noexcept {
  const od::Definition& definition = context_.access.dictionary().definition();
  rpdoCount_ = 0;
  tpdoCount_ = 0;
  for (size_t i = 0; i < definition.objectCount; ++i) {
    const uint16_t index = definition.objects[i].index;
    if (index >= kRpdoCommunicationFirst && index <= kRpdoCommunicationLast &&
        rpdoCount_ < rpdoCapacity_) {
      rpdos_[rpdoCount_++].bind(index);
    } else if (index >= kTpdoCommunicationFirst && index <= kTpdoCommunicationLast &&
               tpdoCount_ < tpdoCapacity_) {
      tpdos_[tpdoCount_++].bind(index);
    }
  }
  context_.tpdos = tpdos_;
  if (context_.profile.tpdoAnswersRpdo) {
    constexpr uint16_t kAnswerOffset = kTpdoCommunicationFirst - kRpdoCommunicationFirst;
    for (size_t i = 0; i < rpdoCount_; ++i) {
      const auto answer = static_cast<uint16_t>(rpdos_[i].communicationIndex() + kAnswerOffset);
      size_t tpdo = 0;
      if (findChannel(false, answer, &tpdo) != nullptr) {
        rpdos_[i].answerWith(tpdo);
      }
    }
  }
}

void PdoEngine::configure() noexcept {
  running_ = false;
  for (size_t i = 0; i < rpdoCount_; ++i) {
    configureChannel(true, i);
  }
  for (size_t i = 0; i < tpdoCount_; ++i) {
    configureChannel(false, i);
  }
}

void PdoEngine::configureChannel(bool receive, size_t number) noexcept {
  AbortCode resolved = AbortCode::kNone;
  if (receive) {
    resolved = rpdos_[number].configure(context_);
  } else {
    TpdoChannel& tpdo = tpdos_[number];
    resolved = tpdo.configure(context_);
    if (running_) {
      tpdo.restart(context_, context_.clock.now);
    } else {
      tpdo.stop();
    }
  }
  if (resolved != AbortCode::kNone) {
    ++unresolvableMappings_;
  }
}

void PdoEngine::refreshMappings() noexcept {
  for (size_t i = 0; i < rpdoCount_; ++i) {
    rpdos_[i].resolveMapping(context_);
  }
  for (size_t i = 0; i < tpdoCount_; ++i) {
    tpdos_[i].resolveMapping(context_);
  }
}

void PdoEngine::start(Microseconds now) noexcept {
  running_ = true;
  context_.syncWindowEnd = kNever;
  for (size_t i = 0; i < tpdoCount_; ++i) {
    tpdos_[i].start(context_, now, context_.profile.tpdoOnEnteringOperational);
  }
}

void PdoEngine::stop() noexcept {
  running_ = false;
  for (size_t i = 0; i < rpdoCount_; ++i) {
    rpdos_[i].stop();
  }
  for (size_t i = 0; i < tpdoCount_; ++i) {
    tpdos_[i].stop();
  }
}

bool PdoEngine::remoteRequest(size_t channel, Microseconds now) noexcept {
  if (!running_ || !tpdos_[channel].valid()) {
    return false;
  }
  tpdos_[channel].onRemoteRequest(context_, now);
  return true;
}

void PdoEngine::onSync(uint8_t counter, Microseconds now, Microseconds windowEnd) noexcept {
  context_.syncWindowEnd = windowEnd;
  if (!running_) {
    return;
  }
  for (size_t i = 0; holding_ && i < rpdoCount_; ++i) {
    // (built for size, every RPDO is asked: onSync() of one that holds nothing does nothing)
    if ((!kExpandFastPaths || rpdos_[i].holding()) && !rpdos_[i].onSync(context_)) {
      ++rpdosRefused_;
    }
  }
  holding_ = false;
  for (size_t i = 0; i < tpdoCount_; ++i) {
    // (built for size, every TPDO is asked: onSync() of one that is not synchronous does nothing)
    if (!kExpandFastPaths || tpdos_[i].synchronous()) {
      tpdos_[i].onSync(context_, counter, now, windowEnd);
    }
  }
}

void PdoEngine::process(Microseconds now) noexcept {
  if (!running_) {
    return;
  }
  for (size_t i = 0; i < rpdoCount_; ++i) {
    rpdos_[i].process(context_, now);
  }
  for (size_t i = 0; i < tpdoCount_; ++i) {
    tpdos_[i].process(context_, now);
  }
}

Microseconds PdoEngine::nextDeadline() const noexcept {
  Microseconds next = kNever;
  if (!running_) {
    return next;
  }
  for (size_t i = 0; i < rpdoCount_; ++i) {
    next = earliest(next, rpdos_[i].nextDeadline());
  }
  for (size_t i = 0; i < tpdoCount_; ++i) {
    next = earliest(next, tpdos_[i].nextDeadline(context_.clock.now));
  }
  return next;
}

void PdoEngine::markChanged(uint16_t index, uint8_t subIndex) noexcept {
  const od::EntryRef ref = context_.access.dictionary().find(index, subIndex);
  if (!ref.valid()) {
    return;
  }
  for (size_t i = 0; i < tpdoCount_; ++i) {
    if (tpdos_[i].maps(ref)) {
      tpdos_[i].signalEvent(context_.clock);
    }
  }
}

bool PdoEngine::requestTransmission(uint16_t communicationIndex) noexcept {
  TpdoChannel* tpdo = findTpdo(communicationIndex);
  if (tpdo == nullptr) {
    return false;
  }
  tpdo->signalEvent(context_.clock);
  return true;
}

const PdoChannel* PdoEngine::findChannel(bool receive, uint16_t communicationIndex,
                                         size_t* number) const noexcept {
  const size_t count = receive ? rpdoCount_ : tpdoCount_;
  for (size_t i = 0; i < count; ++i) {
    const PdoChannel* found = receive ? static_cast<const PdoChannel*>(&rpdos_[i]) : &tpdos_[i];
    if (found->communicationIndex() == communicationIndex) {
      *number = i;
      return found;
    }
  }
  return nullptr;
}

TpdoChannel* PdoEngine::findTpdo(uint16_t communicationIndex) noexcept {
  for (size_t i = 0; i < tpdoCount_; ++i) {
    if (tpdos_[i].communicationIndex() == communicationIndex) {
      return &tpdos_[i];
    }
  }
  return nullptr;
}

AbortCode PdoEngine::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                           const uint8_t* data, size_t length) noexcept {
  const uint16_t index = ref.index();
  // 0x1400..0x1BFF (kFirst..kLast, the range the hook serves): a mapping parameter is 0x200
  // above its communication parameter, 0x1600..0x17FF or 0x1A00..0x1BFF.
  const bool mapping = (index & kMappingOffset) != 0U;
  const auto communicationIndex = static_cast<uint16_t>(index & ~kMappingOffset);
  const bool receive = index < kTpdoCommunicationFirst;
  // The channel the parameter belongs to: an RPDO's or a TPDO's, or none (a plain entry).
  size_t number = 0;
  const PdoChannel* pdo = findChannel(receive, communicationIndex, &number);
  if (pdo == nullptr) {
    return dictionary.write(ref, data, length);
  }
  const AbortCode verdict = mapping ? checkMappingWrite(*pdo, receive, ref, data, length)
                                    : checkCommunicationWrite(*pdo, receive, ref, data, length);
  if (verdict != AbortCode::kNone) {
    return verdict;
  }
  const AbortCode written = dictionary.write(ref, data, length);
  if (written != AbortCode::kNone) {
    return written;
  }
  configureChannel(receive, number);
  context_.routes.invalidate();
  return AbortCode::kNone;
}

}  // namespace costa
