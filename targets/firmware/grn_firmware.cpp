// The Gefran GRN angle sensor as a firmware image, on the mailbox stand-in controller, with
// the simulated hall chips (targets/gefran/hall_sensors.hpp) and parameters in RAM.
#include "dummy_can.hpp"
#include "gefran_target.hpp"
#include "grn_od.hpp"
#include "mailbox_loop.hpp"

costa::firmware::Mailbox costaMailbox;

namespace {
using Grn = costa::gefran::GefranTarget<costa::gen::grn::Values, costa::gen::grn::Capacity>;
costa::firmware::DummyCan can(costaMailbox);
Grn target(costa::gen::grn::kDefinition, can, costa::gefran::kFactoryNodeId, nullptr, false);
}  // namespace

int main() {
  costa::firmware::runOnMailbox(target, can, costaMailbox);
}
