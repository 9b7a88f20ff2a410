#include "costa/node_guarding.hpp"

#include "costa/cob_ids.hpp"

namespace costa {

void NodeGuarding::reset(uint8_t nodeId, uint8_t toggleStart) noexcept {
  nodeId_ = nodeId;
  toggle_ = static_cast<uint8_t>(toggleStart & 1U);
  guarded_ = false;
  expired_ = false;
  deadline_ = kNever;
}

Microseconds NodeGuarding::lifeTime() const noexcept {
  return millisecondsToMicroseconds(dictionary_.readUnsigned(kGuardTimeIndex, 0, 0)) *
         dictionary_.readUnsigned(kLifeTimeFactorIndex, 0, 0);
}

NodeGuarding::Event NodeGuarding::onRequest(NmtState state, Microseconds now) noexcept {
  CanFrame reply;
  reply.id = cob::kErrorControlBase + nodeId_;
  reply.dlc = 1;
  reply.data[0] = static_cast<uint8_t>(static_cast<uint8_t>(state) | (toggle_ << 7U));
  tx_.send(reply);
  toggle_ ^= 1U;
  guarded_ = true;
  const Microseconds life = lifeTime();
  deadline_ = life == 0U ? kNever : now + life;
  clock_.schedule(deadline_);
  if (expired_) {
    expired_ = false;
    return Event::kResumed;
  }
  return Event::kNone;
}

NodeGuarding::Event NodeGuarding::process(Microseconds now) noexcept {
  if (!guarded_ || expired_ || deadline_ == kNever || now < deadline_) {
    return Event::kNone;
  }
  expired_ = true;
  return Event::kLifeTimeExpired;
}

AbortCode NodeGuarding::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                              const uint8_t* data, size_t length) noexcept {
  const AbortCode written = dictionary.write(ref, data, length);
  if (written == AbortCode::kNone && guarded_ && !expired_) {
    const Microseconds life = lifeTime();
    deadline_ = life == 0U ? kNever : clock_.now + life;
    clock_.schedule(deadline_);
  }
  return written;
}

}  // namespace costa
