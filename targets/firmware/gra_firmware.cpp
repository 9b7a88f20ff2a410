// The Gefran GRA angle sensor as a firmware image, on the mailbox stand-in controller, with
// the simulated hall chips (targets/gefran/hall_sensors.hpp) and parameters in RAM.
#include "dummy_can.hpp"
#include "gefran_target.hpp"
#include "gra_od.hpp"
#include "mailbox_loop.hpp"

costa::firmware::Mailbox costaMailbox;

namespace {
using Gra = costa::gefran::GefranTarget<costa::gen::gra::Values, costa::gen::gra::Capacity>;
costa::firmware::DummyCan can(costaMailbox);
Gra target(costa::gen::gra::kDefinition, can, costa::gefran::kFactoryNodeId, nullptr, false);
}  // namespace

int main() {
  costa::firmware::runOnMailbox(target, can, costaMailbox);
}
