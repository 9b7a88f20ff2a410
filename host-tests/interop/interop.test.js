// node-canopen (an independent CANopen master) against costa-slave over SocketCAN, for every
// device: dictionary reads and writes checked against the device's EDS, segmented and block
// transfers, PDO remapping and exchange, NMT, the heartbeat consumer and LSS Fastscan.
// Run by tools/interop (inside the vcan VM when the kernel has no vcan); see docs/interop.md.
'use strict';

const { describe, test, before, after } = require('node:test');
const assert = require('node:assert/strict');

const { Bus } = require('./lib/bus');
const { Slave } = require('./lib/slave');
const { Sdo, hex } = require('./lib/sdo');
const { loadDeviceEds, listDevices } = require('./lib/device_eds');
const { devices } = require('./lib/devices');
const dictionary = require('./lib/dictionary');
const transfers = require('./lib/transfers');
const pdo = require('./lib/pdo');
const nmt = require('./lib/nmt');
const lss = require('./lib/lss');

const iface = process.env.COSTA_INTEROP_IFACE || 'vcan0';
// The master's own node-id: its heartbeat feeds the slave's heartbeat consumer. Not 0x7F,
// which the M-series watches on its own (errata-m-series W7).
const masterId = 0x70;
const only = process.env.COSTA_INTEROP_DEVICES ? process.env.COSTA_INTEROP_DEVICES.split(',') : null;

// A device costa-slave runs but this suite does not know would be left out silently.
test('the suite knows every device costa-slave runs', () => {
  assert.deepEqual(listDevices(), Object.keys(devices));
});

for (const [device, config] of Object.entries(devices)) {
  if (only && !only.includes(device)) {
    continue;
  }
  describe(device, () => {
    const eds = loadDeviceEds(device);
    const nodeId = config.nodeId;
    let bus;
    let slave;
    let sdo;
    const context = { device, eds, nodeId, masterId };

    before(async () => {
      bus = new Bus(iface, masterId);
      const bootUp = bus.expectFrame(
        (f) => f.id === 0x700 + nodeId && f.data.length === 1 && f.data[0] === 0,
        5000,
        'boot-up',
      );
      slave = new Slave(device, { iface, nodeId });
      await bootUp;
      sdo = new Sdo(bus, nodeId);
      Object.assign(context, { bus, sdo });
    });

    after(async () => {
      const status = slave ? await slave.stop() : { code: 0, signal: null };
      bus.close();
      assert.deepEqual(status, { code: 0, signal: null }, `costa-slave exit\n${slave ? slave.output : ''}`);
    });

    test('every readable entry: size as its EDS type, constants as their default', async (t) => {
      const report = await dictionary.readAll(context);
      context.reads = report.reads;
      for (const note of report.notes) {
        t.diagnostic(note);
      }
      assert.deepEqual(report.problems, []);
    });

    test('every writable entry at its limits and one past', async (t) => {
      const report = await dictionary.writeLimits(context);
      for (const note of report.notes) {
        t.diagnostic(note);
      }
      assert.deepEqual(report.problems, []);
    });

    test('segmented and block transfer of the largest object', async (t) => {
      const report = await transfers.largest(context);
      for (const note of report.notes) {
        t.diagnostic(note);
      }
      assert.deepEqual(report.problems, []);
    });

    test('TPDO and RPDO remapped and exchanged', async (t) => {
      const report = await pdo.remapAndExchange(context);
      for (const note of report.notes) {
        t.diagnostic(note);
      }
      assert.deepEqual(report.problems, []);
    });

    test('NMT start, stop, pre-operational, reset node and reset communication', async (t) => {
      const report = await nmt.states(context);
      for (const note of report.notes) {
        t.diagnostic(note);
      }
      assert.deepEqual(report.problems, []);
    });

    test('heartbeat consumer timeout', async (t) => {
      const report = await nmt.heartbeatConsumer(context);
      for (const note of report.notes) {
        t.diagnostic(note);
      }
      assert.deepEqual(report.problems, []);
    });

    test('LSS Fastscan finds an unconfigured node and gives it a node-id', async (t) => {
      const supported = Number(eds.deviceInfo['LSS_Supported'] || 0) === 1;
      if (!supported) {
        t.skip('LSS_Supported=0 in the EDS');
        return;
      }
      // The configured slave leaves the bus first: Fastscan wants the only unconfigured node.
      const status = await slave.stop();
      slave = null;
      assert.deepEqual(status, { code: 0, signal: null });
      const report = await lss.fastscan(context, (id) => new Slave(device, { iface, nodeId: id }));
      for (const note of report.notes) {
        t.diagnostic(note);
      }
      assert.deepEqual(report.problems, []);
    });
  });
}
