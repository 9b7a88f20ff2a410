#include "slave_tracer.hpp"

#include <cstdio>

#include "frame_text.hpp"

namespace costa::host {

SlaveTracer::SlaveTracer(bool enabled, bool labelled, port::LinuxMonotonicClock& clock)
    : enabled_(enabled), labelled_(labelled), clock_(clock), epoch_(clock.nowMicroseconds()) {}

void SlaveTracer::attach(DeviceTarget& target) {
  nodes_.push_back(
      Traced{&target, std::make_unique<FrameTracer>(&target.node().dictionary(), target.names(),
                                                    target.node().profile())});
}

void SlaveTracer::sent(size_t index, const CanFrame& frame) {
  if (enabled_) {
    frameLine("tx", &nodes_[index], frame);
  }
}

void SlaveTracer::received(const CanFrame& frame) {
  if (enabled_) {
    frameLine("rx", nodes_.size() == 1U ? nodes_.data() : addressed(frame), frame);
  }
}

SlaveTracer::Traced* SlaveTracer::addressed(const CanFrame& frame) {
  const uint32_t nodeId = frame.id & 0x7FU;
  if (frame.extended || nodeId == 0U || frame.id >= 0x780U) {
    return nullptr;  // NMT, SYNC, TIME, LSS and everything above the error control range
  }
  for (Traced& node : nodes_) {
    if (node.target->node().nodeId() == nodeId) {
      return &node;
    }
  }
  return nullptr;
}

std::string SlaveTracer::label(const Traced* node) const {
  if (!labelled_) {
    return "";
  }
  if (node == nullptr) {
    return "@-- ";
  }
  char text[8];
  std::snprintf(text, sizeof(text), "@%02X ", node->target->node().nodeId());
  return text;
}

void SlaveTracer::frameLine(const char* direction, const Traced* node, const CanFrame& frame) {
  const std::string meaning = node != nullptr
                                  ? node->decoder->describe(frame, node->target->node().nodeId())
                                  : generic_.describe(frame, 0);
  print(label(node), direction, formatFrame(frame), meaning);
}

void SlaveTracer::errorFrame(const port::SocketCanEvents& events) {
  if (!enabled_) {
    return;
  }
  std::string meaning;
  for (const CanControllerEvent event : events) {
    meaning += meaning.empty() ? "controller: " : ", ";
    meaning += controllerEventName(event);
  }
  print("", "rx", "error frame", meaning);
}

void SlaveTracer::counters(const SlaveCounters& now) {
  if (!enabled_ || now == shown_) {
    return;
  }
  shown_ = now;
  print("", "--", "counters", describeCounters(now));
}

void SlaveTracer::bitRate(uint32_t bitsPerSecond) {
  if (!enabled_) {
    return;
  }
  char text[40];
  if (bitsPerSecond % 1000U == 0U) {
    std::snprintf(text, sizeof(text), "bit rate now %u kbit/s", bitsPerSecond / 1000U);
  } else {
    std::snprintf(text, sizeof(text), "bit rate now %u bit/s", bitsPerSecond);
  }
  print("", "--", text, "");
}

void SlaveTracer::indicators(size_t index, const std::string& states) {
  if (!enabled_) {
    return;
  }
  print(label(&nodes_[index]), "--", "indicators", states);
}

void SlaveTracer::print(const std::string& label, const char* direction, const std::string& what,
                        const std::string& meaning) {
  const uint64_t elapsed = clock_.nowMicroseconds() - epoch_;
  std::printf("%5llu.%06llu %s%s %-32s %s\n", static_cast<unsigned long long>(elapsed / 1000000U),
              static_cast<unsigned long long>(elapsed % 1000000U), label.c_str(), direction,
              what.c_str(), meaning.c_str());
  std::fflush(stdout);
}

}  // namespace costa::host
