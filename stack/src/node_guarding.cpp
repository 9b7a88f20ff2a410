#include "costa/node_guarding.hpp"

#include "costa/cob_ids.hpp"
#include "costa/heartbeat_producer.hpp"
#include "costa/shift_arithmetic.hpp"

namespace costa {

void NodeGuarding::reset(uint8_t nodeId, uint8_t toggleStart) noexcept {
  nodeId_ = nodeId;
  toggle_ = static_cast<uint8_t>(toggleStart & 1U);
  guarded_ = false;
  expired_ = false;
  life_.stop();
}

uint64_t NodeGuarding::lifeTime() const noexcept {
  // Up to 65,535 ms x 255: more than LongTimer's steps, as CiA 301 allows.
  const uint64_t guardTime = multiply(dictionary_.readUnsigned32(kGuardTimeIndex, 0, 0), 1000U);
  return multiply(guardTime, dictionary_.readUnsigned32(kLifeTimeFactorIndex, 0, 0));
}

void NodeGuarding::restartLife(Microseconds now) noexcept {
  const uint64_t life = lifeTime();
  if (life == 0U) {
    life_.stop();
  } else {
    life_.start(now, life);
    clock_.schedule(life_.next());
  }
}

NodeGuarding::Event NodeGuarding::onRequest(NmtState state, Microseconds now) noexcept {
  const auto reply = static_cast<uint8_t>(static_cast<uint8_t>(state) | (toggle_ << 7U));
  tx_.send(cob::kErrorControlBase + nodeId_, &reply, 1);
  toggle_ ^= 1U;
  guarded_ = true;
  restartLife(now);
  if (expired_) {
    expired_ = false;
    return Event::kResumed;
  }
  return Event::kNone;
}

NodeGuarding::Event NodeGuarding::process(Microseconds now) noexcept {
  if (!guarded_ || expired_ || !life_.fired(now)) {
    return Event::kNone;
  }
  if (dictionary_.readUnsigned32(HeartbeatProducer::kIndex, 0, 0) != 0U) {
    // The heartbeat producer started while guarding ran: requests are no longer answered
    // (CiA 301 7.2.8.3.2), so the life time ran out for want of them. Life guarding stops
    // until the next answered request.
    ignoreRequest();
    return Event::kNone;
  }
  expired_ = true;
  return Event::kLifeTimeExpired;
}

AbortCode NodeGuarding::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                              const uint8_t* data, size_t length) noexcept {
  const AbortCode written = dictionary.write(ref, data, length);
  if (written == AbortCode::kNone && guarded_ && !expired_) {
    restartLife(clock_.now);
  }
  return written;
}

}  // namespace costa
