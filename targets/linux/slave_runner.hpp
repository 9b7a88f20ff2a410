// The Linux slave's event loop: one socket and one wait for the earliest deadline of all nodes
// (local_bus.hpp joins the nodes into one bus), --control commands, a clean stop on
// SIGINT/SIGTERM.
#pragma once

#include "device_target.hpp"
#include "slave_options.hpp"

namespace costa::host {

/// What the command line gives node `index` (0-based, in the command line's order) as it is
/// created: its node-id, its storage file, the SDO timeout, the bit rate control `bitRate`, and
/// serial number index + 1 when there are several nodes.
TargetOptions nodeTargetOptions(const SlaveOptions& options, size_t index,
                                CanBitRateControl& bitRate);

/// Runs the nodes described by `options` until SIGINT or SIGTERM. Returns the process exit
/// status: 0 after a clean stop, 1 when the interface or a device cannot be set up (one line on
/// stderr says why).
int runSlave(const SlaveOptions& options);

}  // namespace costa::host
