// LSS (CiA 305): Fastscan finds a node started without a node-id, gives it one, and the node
// boots with it.
'use strict';

const { hex } = require('./sdo');

// Fastscan counts a bit as 1 when no answer comes within this time: under an emulated CPU the
// slave's answer takes some milliseconds, node-canopen's 20 ms default is too short.
const fastscanBitMs = 150;

async function fastscan({ eds, bus, nodeId }, startSlave) {
  const problems = [];
  const notes = [];
  const slave = startSlave(255);
  // The node without node-id sends nothing (no boot-up); give the process time to open its socket.
  await new Promise((resolve) => setTimeout(resolve, 1500));
  try {
    const identity = eds.getIdentity();
    const found = await bus.master.lss.fastscan({ timeout: fastscanBitMs });
    if (!found) {
      problems.push('Fastscan found no node');
      return { problems, notes };
    }
    notes.push(`Fastscan: vendor ${hex(found.vendorId)} product ${hex(found.productCode)} revision ${hex(found.revisionNumber)} serial ${hex(found.serialNumber)}`);
    if (identity && identity.vendorId !== undefined && found.vendorId !== identity.vendorId) {
      problems.push(`vendor-id ${hex(found.vendorId)}, EDS ${hex(identity.vendorId)}`);
    }
    if (identity && identity.productCode !== undefined && found.productCode !== identity.productCode) {
      problems.push(`product code ${hex(found.productCode)}, EDS ${hex(identity.productCode)}`);
    }
    await bus.master.lss.configureNodeId(nodeId, 1000);
    const bootUp = bus.expectFrame((f) => f.id === 0x700 + nodeId && f.data.length === 1 && f.data[0] === 0, 3000, `boot-up of node ${nodeId}`);
    // Back to waiting: CiA 305 lets the newly configured node-id take effect (NMT reset
    // communication, boot-up).
    bus.master.lss.switchModeGlobal(0);
    await bootUp;
    notes.push(`configured node-id ${nodeId}, boot-up seen`);
    const sdo = new (require('./sdo').Sdo)(bus, nodeId);
    const values = [];
    for (let sub = 1; sub <= 4; sub++) {
      const r = await sdo.upload(0x1018, sub);
      values.push(r.abort === undefined ? Buffer.from(r.data).readUInt32LE(0) : undefined);
    }
    const expected = [found.vendorId, found.productCode, found.revisionNumber, found.serialNumber];
    if (values.join() !== expected.join()) {
      problems.push(`0x1018 reads ${values.map((v) => hex(v)).join(' ')}, Fastscan found ${expected.map((v) => hex(v)).join(' ')}`);
    }
  } catch (error) {
    problems.push(error.message);
  } finally {
    const status = await slave.stop();
    if (status.code !== 0) {
      problems.push(`costa-slave --node-id 255 exited ${JSON.stringify(status)}\n${slave.output}`);
    }
  }
  return { problems, notes };
}

module.exports = { fastscan };
