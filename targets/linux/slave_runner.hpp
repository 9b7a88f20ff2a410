// The Linux slave's event loop: SocketCAN in and out, timers from the node's deadlines,
// a clean stop on SIGINT/SIGTERM.
#pragma once

#include "slave_options.hpp"

namespace costa::host {

/// Runs the slave described by `options` until SIGINT or SIGTERM. Returns the process exit
/// status: 0 after a clean stop, 1 when the interface or device cannot be set up (one line on
/// stderr says why).
int runSlave(const SlaveOptions& options);

}  // namespace costa::host
