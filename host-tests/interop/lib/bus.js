// The master's side of the bus: a SocketCAN channel (the npm package socketcan) shared by a
// node-canopen Device (the master) and the test's own observers of raw frames.
'use strict';

const can = require('socketcan');
const { Device, Eds } = require('canopen');

class Bus {
  constructor(iface, masterId) {
    this.channel = can.createRawChannel(iface, true);
    this.observers = new Set();
    this.master = new Device({ eds: new Eds(), id: masterId, enableLss: false });
    // node-canopen hands out {id, data}; the binding wants the frame format spelt out (11-bit,
    // data frame), else it sends nothing useful.
    this.master.addListener('message', ({ id, data }) => this.send(id, data));
    this.channel.addListener('onMessage', (frame) => {
      if (frame.ext || frame.rtr) {
        return;
      }
      for (const observer of [...this.observers]) {
        observer(frame);
      }
      this.master.receive({ id: frame.id, data: frame.data });
    });
    this.channel.start();
    this.master.start();
    this.master.lss.start();
  }

  send(id, data) {
    this.channel.send({ id, ext: false, rtr: false, data: Buffer.from(data) });
  }

  // Resolves with the first frame for which match(frame) is true, received within timeoutMs
  // from now; rejects on timeout. Call before the action that causes the frame.
  expectFrame(match, timeoutMs, what) {
    return new Promise((resolve, reject) => {
      const observer = (frame) => {
        if (match(frame)) {
          clearTimeout(timer);
          this.observers.delete(observer);
          resolve(frame);
        }
      };
      const timer = setTimeout(() => {
        this.observers.delete(observer);
        reject(new Error(`no ${what} within ${timeoutMs} ms`));
      }, timeoutMs);
      this.observers.add(observer);
    });
  }

  // Collects every frame while the promise returned by action() runs.
  async record(action) {
    const frames = [];
    const observer = (frame) => frames.push(frame);
    this.observers.add(observer);
    try {
      await action();
    } finally {
      this.observers.delete(observer);
    }
    return frames;
  }

  close() {
    this.master.stop();
    this.master.lss.stop();
    this.channel.stop();
  }
}

module.exports = { Bus };
