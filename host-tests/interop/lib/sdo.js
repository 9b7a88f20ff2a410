// SDO access through node-canopen's client, with the server's initiate response kept so that
// the suite can see what node-canopen's result hides (size indicated or not).
'use strict';

// node-canopen's SDO client times out after 30 ms by default, too short for a slave running
// under an emulated CPU. 3 s: a busy machine running the VM has stalled a segmented upload for
// more than 1 s; when something is really missing it still fails within seconds.
const sdoTimeoutMs = 3000;

class Sdo {
  constructor(bus, nodeId) {
    this.bus = bus;
    this.nodeId = nodeId;
    bus.master.eds.addSdoClientParameter(nodeId, 0x600 + nodeId, 0x580 + nodeId);
  }

  // { data, abort, initiate } where abort is the abort code (number) when refused and
  // initiate the server's first answer frame.
  async upload(index, subIndex, { block = false } = {}) {
    return this._transfer(() =>
      this.bus.master.sdo.upload({
        deviceId: this.nodeId,
        index,
        subIndex,
        timeout: sdoTimeoutMs,
        blockTransfer: block,
      }),
    );
  }

  async download(index, subIndex, data, { block = false } = {}) {
    return this._transfer(() =>
      this.bus.master.sdo.download({
        deviceId: this.nodeId,
        index,
        subIndex,
        data: Buffer.from(data),
        timeout: sdoTimeoutMs,
        blockTransfer: block,
      }),
    );
  }

  async _transfer(start) {
    let result = {};
    const frames = await this.bus.record(async () => {
      try {
        result.data = await start();
      } catch (error) {
        if (typeof error.code !== 'number') {
          throw error;
        }
        result.abort = error.code;
      }
    });
    result.initiate = frames.find((f) => f.id === 0x580 + this.nodeId);
    return result;
  }
}

function hex(n, digits = 8) {
  return '0x' + (Number(n) >>> 0).toString(16).toUpperCase().padStart(digits, '0');
}

module.exports = { Sdo, hex, sdoTimeoutMs };
