#include "script_player.hpp"

namespace costa::replay {
namespace {

bool ignored(const Script& script, const CanFrame& frame) noexcept {
  for (size_t i = 0; i < script.ignoredCount; ++i) {
    if (!frame.extended && frame.id == script.ignored[i]) {
      return true;
    }
  }
  return false;
}

/// The next frame that is not ignored; false when none.
bool nextFrame(const Script& script, VirtualBus& bus, CanFrame* frame) noexcept {
  while (bus.receive(frame)) {
    if (!ignored(script, *frame)) {
      return true;
    }
  }
  return false;
}

/// True when `actual` matches `expected` except in the data bytes flagged in `wildcards`.
bool matches(const CanFrame& expected, uint8_t wildcards, const CanFrame& actual) noexcept {
  if (expected.id != actual.id || expected.extended != actual.extended ||
      expected.rtr != actual.rtr || expected.dlc != actual.dlc) {
    return false;
  }
  if (expected.rtr) {
    return true;
  }
  for (unsigned i = 0; i < expected.dlc && i < 8U; ++i) {
    if ((wildcards & (1U << i)) == 0U && expected.data[i] != actual.data[i]) {
      return false;
    }
  }
  return true;
}

/// Starts a verdict: "NAME:LINE: ".
Text& at(Text& verdict, const Script& script, const Step& step) noexcept {
  verdict.clear();
  return verdict.append(script.name).append(":").appendDecimal(step.line).append(": ");
}

bool transmitted(const Script& script, const Step& step, VirtualBus& bus, Text& verdict) noexcept {
  for (;;) {
    CanFrame actual;
    if (!bus.receive(&actual)) {
      at(verdict, script, step).append("expected tx ").appendFrame(step.frame);
      verdict.append(" but the slave sent nothing");
      return false;
    }
    if (matches(step.frame, step.wildcards, actual)) {
      return true;
    }
    if (!ignored(script, actual)) {
      at(verdict, script, step).append("expected tx ").appendFrame(step.frame);
      verdict.append("\n    but the slave sent ").appendFrame(actual);
      return false;
    }
  }
}

bool simulated(const Script& script, const Step& step, VirtualBus& bus, Text& verdict) noexcept {
  FixedText<96> why;
  if (bus.simulate(step.command, why)) {
    return true;
  }
  at(verdict, script, step);
  if (why.empty()) {
    verdict.append(bus.failure());
  } else {
    verdict.append("sim ").append(step.command).append(": ").append(why.c_str());
  }
  return false;
}

bool silent(const Script& script, const Step& step, VirtualBus& bus, Text& verdict) noexcept {
  CanFrame extra;
  if (!nextFrame(script, bus, &extra)) {
    return true;
  }
  at(verdict, script, step).append("expected silence but the slave sent ").appendFrame(extra);
  return false;
}

bool played(const Script& script, const Step& step, VirtualBus& bus, Text& verdict) noexcept {
  bool running = true;
  switch (step.kind) {
    case StepKind::kReceive: running = bus.send(step.frame); break;
    case StepKind::kTransmit: return transmitted(script, step, bus, verdict);
    case StepKind::kSimulate: return simulated(script, step, bus, verdict);
    case StepKind::kWait: running = bus.wait(step.milliseconds); break;
    case StepKind::kSilence: return silent(script, step, bus, verdict);
  }
  if (!running) {
    at(verdict, script, step).append(bus.failure());
  }
  return running;
}

}  // namespace

bool playScript(const Script& script, VirtualBus& bus, Text& verdict) noexcept {
  verdict.clear();
  if (!bus.powerOn()) {
    verdict.append(script.name).append(": ").append(bus.failure());
    return false;
  }
  for (size_t i = 0; i < script.stepCount; ++i) {
    if (!played(script, script.steps[i], bus, verdict)) {
      return false;
    }
  }
  CanFrame extra;
  if (nextFrame(script, bus, &extra)) {
    verdict.append(script.name).append(": after the last step the slave also sent ");
    verdict.appendFrame(extra);
    return false;
  }
  return true;
}

}  // namespace costa::replay
