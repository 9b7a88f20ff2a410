// costa-footprint-a.elf and costa-footprint-b.elf: a bare node with CANopenNode's example
// dictionary, the smallest image a device with those objects needs (tools/budgets.txt holds
// their flash and RAM). Built like every firmware image (targets/firmware: startup.cpp,
// cortex_m.ld, newlib-nano, --gc-sections, the no-heap check), with the main loop of the
// example image: frames from the mailbox stand-in controller to the node, then its timers.
//   A (COSTA_FOOTPRINT_B=0): footprint_a.eds, a stack without any optional service, no LSS,
//     no storage.
//   B (COSTA_FOOTPRINT_B=1): footprint_b.eds (plus 0x100C, 0x100D), a stack with all five
//     optional services, LSS on, and a blank storage (accepts every write, keeps nothing).
// The node's capacities are the defaults (DefaultNodeCapacity), as in the device images.
#include "costa/node.hpp"
#include "dummy_can.hpp"

#if COSTA_FOOTPRINT_B
#include "footprint_b_od.hpp"
namespace dictionary = costa::gen::footprint_b;
#else
#include "footprint_a_od.hpp"
namespace dictionary = costa::gen::footprint_a;
#endif

costa::firmware::Mailbox costaMailbox;

namespace {

#if COSTA_FOOTPRINT_B
/// Storage without a medium behind it: reads as erased, takes every write and forgets it.
class BlankStorage final : public costa::NvStorage {
 public:
  static constexpr size_t kSize = 1024;

  size_t size() const noexcept override { return kSize; }
  bool read(size_t offset, uint8_t* destination, size_t length) noexcept override {
    static_cast<void>(offset);
    for (size_t i = 0; i < length; ++i) {
      destination[i] = 0xFF;
    }
    return true;
  }
  bool write(size_t offset, const uint8_t* source, size_t length) noexcept override {
    static_cast<void>(offset);
    static_cast<void>(source);
    static_cast<void>(length);
    return true;
  }
  bool erase(size_t offset, size_t length) noexcept override {
    static_cast<void>(offset);
    static_cast<void>(length);
    return true;
  }
  bool commit() noexcept override { return true; }
};

BlankStorage storage;
#endif

costa::NodeSettings nodeSettings() noexcept {
  costa::NodeSettings settings;
  settings.nodeId = 1;
#if COSTA_FOOTPRINT_B
  settings.lss = true;
  settings.lssBitRates = 0x01DF;  // CiA 305 indices 0..4 and 6..8: every rate of the table
  settings.storage = &storage;
#endif
  return settings;
}

// In static storage, as in the device images.
costa::firmware::DummyCan can(costaMailbox);
costa::NodeInstance<dictionary::Values, dictionary::Capacity> node(dictionary::kDefinition, can,
                                                                   nodeSettings());

}  // namespace

int main() {
  node.start(0);
  for (;;) {
    const costa::Microseconds now = static_cast<costa::Microseconds>(costaMailbox.ticks) * 1000U;
    costa::CanFrame frame;
    while (can.receive(&frame)) {
      node.onFrame(frame, now);
    }
    static_cast<void>(node.process(now));
  }
}
