// A device of the list (targets/devices.hpp) as a firmware image, on the mailbox stand-in
// controller, with its simulated hardware and its parameters in its own memory. The build
// compiles this file once per device, naming it in COSTA_FIRMWARE_DEVICE (CMakeLists.txt).
#include "devices.hpp"
#include "dummy_can.hpp"
#include "mailbox_loop.hpp"

#ifndef COSTA_FIRMWARE_DEVICE
#error "COSTA_FIRMWARE_DEVICE names the device of this image (see CMakeLists.txt)"
#endif

costa::firmware::Mailbox costaMailbox;

namespace {
// In static storage: a device's buffers (the example's 12 KiB scratch pad) would crowd the
// stack. No DeviceConfig: the device's own node-id and memory, no bit rate control.
costa::firmware::DummyCan can(costaMailbox);
costa::devices::COSTA_FIRMWARE_DEVICE target(can, costa::DeviceConfig{});
}  // namespace

int main() {
  costa::firmware::runOnMailbox(target, can, costaMailbox);
}
