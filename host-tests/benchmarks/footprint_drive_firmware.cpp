// costa-footprint-drive.elf and costa-footprint-drive-node.elf: what the CiA 402 drive profile
// (stack/cia402) costs alone. Both are a bare node with the profile's objects
// (host-tests/data/cia402_drive.eds) on the stack with every optional service, no LSS, no
// storage, and the main loop of the footprint images; costa-footprint-drive
// (COSTA_FOOTPRINT_DRIVE=1) adds the drive in front of an axis that never moves. The difference
// of their flash and RAM is the profile's (tools/budgets.txt holds both).
#include "cia402_drive_od.hpp"
#include "costa/node.hpp"
#include "dummy_can.hpp"
#if COSTA_FOOTPRINT_DRIVE
#include "costa/cia402/drive.hpp"
#endif

costa::firmware::Mailbox costaMailbox;

namespace {

namespace dictionary = costa::gen::cia402_drive;

costa::NodeSettings nodeSettings() noexcept {
  costa::NodeSettings settings;
  settings.nodeId = 1;
  return settings;
}

// In static storage, as in the device images.
costa::firmware::DummyCan can(costaMailbox);
costa::NodeInstance<dictionary::Values, dictionary::Capacity> node(dictionary::kDefinition, can,
                                                                   nodeSettings());

#if COSTA_FOOTPRINT_DRIVE
/// An axis that never moves: the profile's own code and nothing of a motor.
class StillAxis final : public costa::cia402::Axis {};
StillAxis axis;
costa::cia402::Drive drive(node, axis, costa::cia402::DriveOptions{});
#endif

}  // namespace

int main() {
  node.start(0);
  for (;;) {
    const costa::Microseconds now = static_cast<costa::Microseconds>(costaMailbox.ticks) * 1000U;
    costa::CanFrame frame;
    while (can.receive(&frame)) {
      node.onFrame(frame, now);
    }
#if COSTA_FOOTPRINT_DRIVE
    drive.update();
#endif
    static_cast<void>(node.process(now));
  }
}
