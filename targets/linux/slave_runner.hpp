// The Linux slave's event loop: one socket and one wait for the earliest deadline of all nodes
// (local_bus.hpp joins the nodes into one bus), --control commands, a clean stop on
// SIGINT/SIGTERM.
#pragma once

#include "slave_options.hpp"

namespace costa::host {

/// Runs the nodes described by `options` until SIGINT or SIGTERM. Returns the process exit
/// status: 0 after a clean stop, 1 when the interface or a device cannot be set up (one line on
/// stderr says why).
int runSlave(const SlaveOptions& options);

}  // namespace costa::host
