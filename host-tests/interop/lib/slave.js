// A costa-slave process for one device on a vcan interface.
'use strict';

const { spawn } = require('node:child_process');
const path = require('node:path');
const { sdoTimeoutMs } = require('./sdo');

const repository = path.resolve(__dirname, '..', '..', '..');

function slavePath() {
  const build = process.env.COSTA_BUILD || path.join(repository, 'build');
  return path.join(build, 'targets', 'linux', 'costa-slave');
}

class Slave {
  constructor(device, { iface = 'vcan0', nodeId } = {}) {
    // The server waits for the master as long as the master waits for it: a stalled VM then
    // fails a transfer on neither side before the other.
    const args = ['--iface', iface, '--sdo-timeout', String(sdoTimeoutMs)];
    if (nodeId !== undefined) {
      args.push('--node-id', String(nodeId));
    }
    args.push(device);
    this.output = '';
    this.exited = new Promise((resolve) => {
      this.process = spawn(slavePath(), args, { stdio: ['ignore', 'pipe', 'pipe'] });
      this.process.stdout.on('data', (d) => (this.output += d));
      this.process.stderr.on('data', (d) => (this.output += d));
      this.process.on('exit', (code, signal) => resolve({ code, signal }));
    });
  }

  // Stops the slave with SIGTERM; resolves with its exit status (0 expected).
  async stop() {
    this.process.kill('SIGTERM');
    return this.exited;
  }
}

module.exports = { Slave, slavePath };
