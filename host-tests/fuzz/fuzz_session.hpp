// One fuzz input run against one device: the events of the input applied in order on a virtual
// clock, every invariant checked after every event.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <string>

namespace costa::fuzz {

/// Powers `device` (a fuzzedDeviceNames() entry) on as the input's header says and applies its
/// events (fuzz_events.hpp). After power-on and after every event it checks:
///  * every frame transmitted since the previous check (frame_rules.hpp), against the CAN-IDs
///    the node may use before and after the event, or at any point since its transmit queue was
///    last empty (a frame queued while the controller refused frames leaves late); and no
///    frame handed to the controller during an LSS bit timing switch or while bus-off;
///  * every dictionary value (dictionary_rules.hpp), and the CAN-IDs its COB-IDs configure
///    (frame_rules.hpp);
///  * the NMT, LSS and SDO state machines (state_rules.hpp);
///  * the stored parameters, whenever the storage was modified (storage_rules.hpp);
///  * every process() call: its deadline is not in the past, and one equal to now is not asked
///    for without end (1000 immediate calls in a row).
/// Time advances like the in-process test bus: from deadline to deadline, process() at each.
/// After 10000 process() calls the input ends with the event that made them (its checks run),
/// so that long waits with a fast timer keep every input short.
/// Returns "" when every check passed, else the first violation with the event and time.
/// With `trace`, appends one line per event and per transmitted frame (costa_fuzz_replay
/// --trace).
std::string runFuzzInput(const std::string& device, const uint8_t* data, size_t size,
                         std::string* trace = nullptr);

}  // namespace costa::fuzz
