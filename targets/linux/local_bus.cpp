#include "local_bus.hpp"

#include <algorithm>

namespace costa::host {

CanTransmitter& LocalBus::nextPort() {
  ports_.push_back(std::make_unique<Port>(*this, ports_.size()));
  return *ports_.back();
}

void LocalBus::attach(std::unique_ptr<DeviceTarget> target) {
  tracer_.attach(*target);
  Slot slot;
  if (tracer_.enabled()) {
    slot.indicators = std::make_unique<NodeIndicators>(target->node());
  }
  slot.target = std::move(target);
  nodes_.push_back(std::move(slot));
}

bool LocalBus::transmit(size_t sender, const CanFrame& frame) {
  if (!socket_.tryTransmit(frame)) {
    nodes_[sender].refused = true;
    return false;
  }
  tracer_.sent(sender, frame);
  if (nodes_.size() > 1U) {
    sent_.push_back(Sent{sender, frame});
  }
  return true;
}

void LocalBus::deliver(size_t index, const CanFrame& frame, Microseconds now) {
  Slot& slot = nodes_[index];
  const Node& node = slot.target->node();
  const uint32_t ignored = node.statistics().framesIgnored;
  slot.target->onFrame(frame, now);
  if (node.statistics().framesIgnored == ignored) {
    slot.due = true;
  }
}

void LocalBus::start(Microseconds now) {
  for (Slot& slot : nodes_) {
    slot.target->start(now);
    slot.due = true;
  }
}

void LocalBus::receive(const CanFrame& frame, Microseconds now) {
  tracer_.received(frame);
  for (size_t i = 0; i < nodes_.size(); ++i) {
    deliver(i, frame, now);
  }
}

void LocalBus::controllerEvent(CanControllerEvent event, Microseconds now) {
  for (Slot& slot : nodes_) {
    slot.target->node().onControllerEvent(event, now);
    slot.due = true;
  }
}

void LocalBus::runDue(Microseconds now) {
  for (size_t i = 0; i < nodes_.size(); ++i) {
    Slot& slot = nodes_[i];
    if (slot.due || slot.refused || reached(now, slot.deadline)) {
      slot.due = false;
      slot.deadline = slot.target->process(now);
      slot.refused = slot.target->node().txPending();
      if (slot.indicators) {
        slot.deadline = earliest(slot.deadline, slot.indicators->process(now));
        const std::string change = slot.indicators->change();
        if (!change.empty()) {
          tracer_.indicators(i, change);
        }
      }
    }
  }
}

Microseconds LocalBus::process() {
  runDue(now());
  while (!sent_.empty()) {
    const Sent sent = sent_.front();
    sent_.pop_front();
    const Microseconds time = now();
    for (size_t i = 0; i < nodes_.size(); ++i) {
      if (i != sent.sender) {
        deliver(i, sent.frame, time);
      }
    }
    runDue(now());
  }
  Microseconds earliestDeadline = kNever;
  for (const Slot& slot : nodes_) {
    earliestDeadline = earliest(earliestDeadline, slot.deadline);
  }
  return earliestDeadline;
}

bool LocalBus::txPending() const {
  return std::any_of(nodes_.begin(), nodes_.end(), [](const Slot& slot) { return slot.refused; });
}

void LocalBus::flushTx() {
  for (Slot& slot : nodes_) {
    if (slot.refused) {
      slot.target->node().flushTx();
      slot.refused = slot.target->node().txPending();
    }
  }
}

}  // namespace costa::host
