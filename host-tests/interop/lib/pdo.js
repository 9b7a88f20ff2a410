// A TPDO and an RPDO remapped by SDO (CiA 301 7.5.2.36 procedure) and exchanged.
'use strict';

const { entriesOf, where } = require('./dictionary');
const { typeSize, typeRange, encode, decode, isSigned } = require('./values');
const { hex } = require('./sdo');
const { skipReason } = require('./devices');

function mappable(e) {
  // node-canopen keeps PDOMapping as the EDS's string ("0" or "1"), so "0" would be truthy.
  return String(e.entry.pdoMapping) === '1' || e.entry.pdoMapping === true;
}

async function write(sdo, problems, index, subIndex, value, size) {
  const r = await sdo.download(index, subIndex, encode(BigInt(value), size));
  if (r.abort !== undefined) {
    problems.push(`write ${index.toString(16)}:${subIndex} = ${hex(value)} aborted ${hex(r.abort)}`);
    return false;
  }
  return true;
}

// A value inside the entry's limits that differs from the current one.
function testValue(e, current) {
  const range = typeRange(e.entry.dataType);
  const low = e.entry.lowLimit !== undefined ? BigInt(e.entry.lowLimit) : range[0];
  const high = e.entry.highLimit !== undefined ? BigInt(e.entry.highLimit) : range[1];
  for (const candidate of [low + 1n, high - 1n, low, high]) {
    if (candidate >= low && candidate <= high && candidate !== current) {
      return candidate;
    }
  }
  return low;
}

async function mapOne(sdo, problems, commIndex, entry, transmissionType) {
  const mapIndex = commIndex + 0x200;
  const cob = await sdo.upload(commIndex, 1);
  if (cob.abort !== undefined) {
    problems.push(`read ${commIndex.toString(16)}:01 aborted ${hex(cob.abort)}`);
    return undefined;
  }
  const cobId = Buffer.from(cob.data).readUInt32LE(0);
  const canId = cobId & 0x7ff;
  const bits = typeSize(entry.entry.dataType) * 8;
  const ok =
    (await write(sdo, problems, commIndex, 1, (cobId | 0x80000000) >>> 0, 4)) &&
    (await write(sdo, problems, mapIndex, 0, 0, 1)) &&
    (await write(sdo, problems, mapIndex, 1, ((entry.index << 16) | (entry.subIndex << 8) | bits) >>> 0, 4)) &&
    (await write(sdo, problems, mapIndex, 0, 1, 1)) &&
    (await write(sdo, problems, commIndex, 2, transmissionType, 1)) &&
    (await write(sdo, problems, commIndex, 1, (cobId & 0x7fffffff) >>> 0, 4));
  return ok ? canId : undefined;
}

function pick(eds, device, accessOk) {
  return entriesOf(eds).find(
    (e) =>
      e.index >= 0x2000 &&
      mappable(e) &&
      accessOk.includes(String(e.entry.accessType).toLowerCase()) &&
      typeRange(e.entry.dataType) &&
      !skipReason(device, e.index, e.subIndex),
  );
}

async function remapAndExchange({ device, eds, sdo, bus, nodeId }) {
  const problems = [];
  const notes = [];
  const { devices } = require('./devices');
  if (devices[device].fixedPdos) {
    notes.push(`skipped: ${devices[device].fixedPdos}`);
    return { problems, notes };
  }
  const hasTpdo = !!eds.getEntry(0x1800) && !!eds.getEntry(0x1a00);
  const hasRpdo = !!eds.getEntry(0x1400) && !!eds.getEntry(0x1600);
  const started = bus.expectFrame((f) => false, 300, 'nothing').catch(() => {});
  bus.master.nmt.startNode(nodeId);
  await started;

  if (hasTpdo) {
    // A writable entry, so that the value the TPDO carries is one the master chose.
    const e = pick(eds, device, ['rw', 'rwr', 'rww']) || pick(eds, device, ['ro']);
    const size = typeSize(e.entry.dataType);
    const viaSync = !!eds.getEntry(0x1005);
    // SYNC-driven (type 1) where the device consumes SYNC, else event-driven with the event timer.
    const canId = await mapOne(sdo, problems, 0x1800, e, viaSync ? 1 : 255);
    if (canId !== undefined) {
      let expected;
      if (String(e.entry.accessType).toLowerCase() !== 'ro') {
        const current = (await sdo.upload(e.index, e.subIndex)).data;
        expected = encode(testValue(e, current ? decode(Buffer.from(current).subarray(0, size), isSigned(e.entry.dataType)) : 0n), size);
        const r = await sdo.download(e.index, e.subIndex, expected);
        if (r.abort !== undefined) {
          problems.push(`${where(e)}: write of the TPDO value aborted ${hex(r.abort)}`);
        }
      }
      if (!viaSync) {
        await write(sdo, problems, 0x1800, 5, 100, 2);
      }
      const frame = bus.expectFrame((f) => f.id === canId, 2000, `TPDO on ${hex(canId, 3)}`);
      if (viaSync) {
        bus.send(0x80, []);
      }
      try {
        const f = await frame;
        notes.push(`TPDO ${hex(canId, 3)} maps ${where(e)}: ${f.data.toString('hex')}`);
        if (f.data.length !== size) {
          problems.push(`TPDO carries ${f.data.length} bytes, mapped ${size}`);
        } else if (expected && !f.data.equals(expected)) {
          problems.push(`TPDO carries ${f.data.toString('hex')}, entry holds ${expected.toString('hex')}`);
        }
      } catch (error) {
        problems.push(error.message);
      }
    }
  } else {
    notes.push('no TPDO in the EDS');
  }

  if (hasRpdo) {
    const e = pick(eds, device, ['rw', 'rww']);
    if (!e) {
      notes.push('RPDO skipped: no readable and writable mappable entry to check the value with');
    } else {
      const size = typeSize(e.entry.dataType);
      const canId = await mapOne(sdo, problems, 0x1400, e, 255);
      if (canId !== undefined) {
        const current = (await sdo.upload(e.index, e.subIndex)).data;
        const value = encode(testValue(e, current ? decode(Buffer.from(current).subarray(0, size), isSigned(e.entry.dataType)) : 0n), size);
        bus.send(canId, value);
        await new Promise((resolve) => setTimeout(resolve, 200));
        const back = await sdo.upload(e.index, e.subIndex);
        notes.push(`RPDO ${hex(canId, 3)} maps ${where(e)}: sent ${value.toString('hex')}`);
        if (back.abort !== undefined || !Buffer.from(back.data).subarray(0, size).equals(value)) {
          problems.push(`RPDO: ${where(e)} reads ${back.abort ? hex(back.abort) : Buffer.from(back.data).toString('hex')} after ${value.toString('hex')}`);
        }
      }
    }
  } else {
    notes.push('no RPDO in the EDS');
  }
  return { problems, notes };
}

module.exports = { remapAndExchange };
