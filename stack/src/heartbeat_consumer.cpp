#include "costa/heartbeat_consumer.hpp"

#include "costa/od/little_endian.hpp"

namespace costa {

void HeartbeatConsumer::configure(bool reset) noexcept {
  const od::Object* object = dictionary_.findObject(kIndex);
  count_ = 0;
  if (reset) {
    for (size_t i = 0; i < capacity_; ++i) {
      monitors_[i] = HeartbeatMonitor{};
    }
  }
  if (object == nullptr) {
    return;
  }
  const unsigned entries = dictionary_.entryCount(*object);
  for (unsigned i = 0; i + 1U < entries && count_ < capacity_; ++i) {
    const auto value = dictionary_.readUnsigned32(kIndex, static_cast<uint8_t>(i + 1U), 0);
    const auto nodeId = static_cast<uint8_t>(value >> 16U);
    const Microseconds time = millisecondsToMicroseconds(value & 0xFFFFU);
    HeartbeatMonitor& monitor = monitors_[count_++];
    if (monitor.nodeId != nodeId || monitor.time != time) {
      // Changed twice before process(): the producer that had timed out is still the one.
      const uint8_t withdrawnFrom = monitor.timedOut ? monitor.nodeId : monitor.withdrawnFrom;
      monitor = HeartbeatMonitor{};  // a changed entry starts over: first heartbeat, then timing
      monitor.nodeId = nodeId;
      monitor.time = time;
      monitor.withdrawnFrom = withdrawnFrom;
    }
  }
}

const HeartbeatMonitor* HeartbeatConsumer::monitor(uint8_t subIndex) const noexcept {
  return subIndex >= 1U && subIndex <= count_ ? &monitors_[subIndex - 1U] : nullptr;
}

HeartbeatConsumer::Event HeartbeatConsumer::onHeartbeat(uint8_t nodeId, uint8_t state,
                                                        Microseconds now) noexcept {
  Event event;
  for (size_t i = 0; i < count_; ++i) {
    HeartbeatMonitor& monitor = monitors_[i];
    if (monitor.nodeId != nodeId || monitor.nodeId == 0U || monitor.time == 0U) {
      continue;
    }
    monitor.active = true;
    monitor.lastState = state;
    monitor.deadline = at(now, monitor.time);
    if (monitor.timedOut) {
      monitor.timedOut = false;
      if (event.kind == EventKind::kNone) {
        event = Event{EventKind::kResumed, nodeId, static_cast<uint8_t>(i + 1U)};
      }
    }
  }
  return event;
}

HeartbeatConsumer::Event HeartbeatConsumer::process(Microseconds now) noexcept {
  for (size_t i = 0; i < count_; ++i) {
    HeartbeatMonitor& monitor = monitors_[i];
    if (monitor.withdrawnFrom != 0U) {
      const Event withdrawn{EventKind::kWithdrawn, monitor.withdrawnFrom,
                            static_cast<uint8_t>(i + 1U)};
      monitor.withdrawnFrom = 0;
      return withdrawn;
    }
    if (monitor.active && !monitor.timedOut && reached(now, monitor.deadline)) {
      monitor.timedOut = true;
      return Event{EventKind::kTimeout, monitor.nodeId, static_cast<uint8_t>(i + 1U)};
    }
  }
  return Event{};
}

Microseconds HeartbeatConsumer::nextDeadline() const noexcept {
  Microseconds next = kNever;
  for (size_t i = 0; i < count_; ++i) {
    const HeartbeatMonitor& monitor = monitors_[i];
    if (monitor.withdrawnFrom != 0U) {
      return atOnce(clock_.now);  // to be reported at once
    }
    if (monitor.active && !monitor.timedOut) {
      next = earliest(next, monitor.deadline);
    }
  }
  return next;
}

AbortCode HeartbeatConsumer::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                                   const uint8_t* data, size_t length) noexcept {
  if (ref.subIndex() != 0U && length == 4U) {
    const uint32_t value = loadU32(data);
    const auto nodeId = static_cast<uint8_t>(value >> 16U);
    if ((value & 0xFF000000U) != 0U) {
      return AbortCode::kInvalidValue;
    }
    if (nodeId != 0U && (value & 0xFFFFU) != 0U) {
      for (unsigned sub = 1; sub < dictionary.entryCount(*ref.object); ++sub) {
        if (sub == ref.subIndex()) {
          continue;
        }
        const auto other = dictionary.readUnsigned32(kIndex, static_cast<uint8_t>(sub), 0);
        if ((other >> 16U) == nodeId && (other & 0xFFFFU) != 0U) {
          return AbortCode::kParameterIncompatible;
        }
      }
    }
  }
  const AbortCode written = dictionary.write(ref, data, length);
  if (written == AbortCode::kNone) {
    configure(false);
    clock_.scheduleNow();  // process() reports a withdrawn entry at once
  }
  return written;
}

}  // namespace costa
