// The SOLO motor controller as a firmware image, on the mailbox stand-in controller. The drive
// is the simulated one (targets/solo/simulated_drive.hpp); a real board replaces it with its
// power stage behind the same DriveBackend interface.
#include "dummy_can.hpp"
#include "mailbox_loop.hpp"
#include "solo_target.hpp"

costa::firmware::Mailbox costaMailbox;

namespace {
costa::firmware::DummyCan can(costaMailbox);
costa::solo::SoloTarget target(can, 1);  // address 1 until one is stored in 0x3001
}  // namespace

int main() {
  costa::firmware::runOnMailbox(target, can, costaMailbox);
}
