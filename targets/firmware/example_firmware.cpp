// The example device as a firmware image (link check of the freestanding core).
#include "dummy_can.hpp"
#include "example_target.hpp"

costa::firmware::Mailbox costaMailbox;

namespace {
// In static storage: the device's buffers (the 12 KiB scratch pad) would crowd the stack.
costa::firmware::DummyCan can(costaMailbox);
costa::example::ExampleTarget target(can, 1);
}  // namespace

int main() {
  target.start(0);
  for (;;) {
    const costa::Microseconds now = static_cast<costa::Microseconds>(costaMailbox.ticks) * 1000U;
    costa::CanFrame frame;
    while (can.receive(&frame)) {
      target.onFrame(frame, now);
    }
    target.process(now);
  }
}
