// NMT state changes seen in the heartbeat, boot-up after the resets, and the heartbeat
// consumer's timeout.
'use strict';

const { encode } = require('./values');
const { hex } = require('./sdo');

const states = { stopped: 0x04, operational: 0x05, preOperational: 0x7f };

function heartbeat(bus, nodeId, state, timeoutMs, what) {
  return bus.expectFrame(
    (f) => f.id === 0x700 + nodeId && f.data.length === 1 && f.data[0] === state,
    timeoutMs,
    what,
  );
}

async function states_({ eds, sdo, bus, nodeId }) {
  const problems = [];
  const notes = [];
  const producer = eds.getEntry(0x1017);
  if (!producer || !['rw', 'rww', 'rwr'].includes(String(producer.accessType).toLowerCase())) {
    problems.push('0x1017 is not writable: the NMT states cannot be watched in the heartbeat');
    return { problems, notes };
  }
  const r = await sdo.download(0x1017, 0, encode(100n, producer.dataType === 7 ? 4 : 2));
  if (r.abort !== undefined) {
    problems.push(`0x1017 = 100 aborted ${hex(r.abort)}`);
    return { problems, notes };
  }
  const steps = [
    ['start remote node', () => bus.master.nmt.startNode(nodeId), states.operational],
    ['stop remote node', () => bus.master.nmt.stopNode(nodeId), states.stopped],
    ['enter pre-operational', () => bus.master.nmt.enterPreOperational(nodeId), states.preOperational],
    ['start remote node', () => bus.master.nmt.startNode(nodeId), states.operational],
    ['reset node', () => bus.master.nmt.resetNode(nodeId), 0x00],
    ['reset communication', () => bus.master.nmt.resetCommunication(nodeId), 0x00],
  ];
  for (const [what, command, state] of steps) {
    // A heartbeat already on its way when the command is sent may still carry the old state:
    // the first one with the new state counts (two producer periods and some margin).
    const seen = heartbeat(bus, nodeId, state, 2000, `${state === 0 ? 'boot-up' : `heartbeat ${hex(state, 2)}`} after ${what}`);
    command();
    try {
      await seen;
      notes.push(`${what}: ${state === 0 ? 'boot-up' : `heartbeat ${hex(state, 2)}`}`);
    } catch (error) {
      problems.push(error.message);
    }
  }
  // After reset node the dictionary has its power-on values: 0x1017 as the EDS says.
  const after = await sdo.upload(0x1017, 0);
  const expected = BigInt(producer.defaultValue ?? 0);
  if (after.abort !== undefined || Buffer.from(after.data).readUIntLE(0, Math.min(after.data.length, 4)) !== Number(expected)) {
    problems.push(`0x1017 after the resets: ${after.abort ? hex(after.abort) : Buffer.from(after.data).toString('hex')}, EDS default ${expected}`);
  }
  return { problems, notes };
}

async function heartbeatConsumer({ device, eds, sdo, bus, nodeId, masterId }) {
  const timeoutState = require('./devices').devices[device].consumerTimeoutState ?? states.preOperational;
  const problems = [];
  const notes = [];
  const consumer = eds.getEntry(0x1016);
  if (!consumer) {
    notes.push('skipped: no 0x1016 in the EDS');
    return { problems, notes };
  }
  // The node operational, so that the consumer's timeout shows in the state too (0x1029:01
  // default 0: to pre-operational on a communication error) when the device sends no EMCY.
  const producer = eds.getEntry(0x1017);
  await sdo.download(0x1017, 0, encode(100n, producer && producer.dataType === 7 ? 4 : 2));
  const running = heartbeat(bus, nodeId, states.operational, 2000, 'operational heartbeat');
  bus.master.nmt.startNode(nodeId);
  await running.catch((error) => problems.push(error.message));
  const timeMs = 300;
  const r = await sdo.download(0x1016, 1, encode((BigInt(masterId) << 16n) | BigInt(timeMs), 4));
  if (r.abort !== undefined) {
    problems.push(`0x1016:01 = producer ${hex(masterId, 2)}, ${timeMs} ms aborted ${hex(r.abort)}`);
    return { problems, notes };
  }
  // The master produces its heartbeat through node-canopen's NMT (its own 0x1017).
  bus.master.eds.setHeartbeatProducerTime(100);
  await new Promise((resolve) => setTimeout(resolve, 600));
  const emcyCob = eds.getEntry(0x1014);
  const emcyId = emcyCob ? 0x80 + nodeId : undefined;
  const timeout = bus.expectFrame(
    (f) =>
      (f.id === emcyId && f.data.length === 8 && f.data.readUInt16LE(0) === 0x8130) ||
      (f.id === 0x700 + nodeId && f.data[0] === timeoutState),
    3000,
    `EMCY 0x8130 or heartbeat ${hex(timeoutState, 2)} after the master's heartbeat stopped`,
  );
  bus.master.eds.setHeartbeatProducerTime(0);
  try {
    const f = await timeout;
    if (f.id === emcyId) {
      notes.push(`EMCY ${f.data.toString('hex')}`);
      if (f.data[3] !== masterId) {
        problems.push(`EMCY 0x8130 names producer ${hex(f.data[3], 2)}, not ${hex(masterId, 2)}`);
      }
    } else {
      notes.push(`heartbeat ${hex(timeoutState, 2)} (no EMCY)`);
    }
  } catch (error) {
    problems.push(error.message);
  }
  return { problems, notes };
}

module.exports = { states: states_, heartbeatConsumer };
