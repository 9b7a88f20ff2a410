// Every entry of the EDS read by SDO, and every writable one written at its limits.
'use strict';

const { typeSize, typeRange, encode, evaluateDefault } = require('./values');
const { hex } = require('./sdo');
const { skipReason } = require('./devices');

const readable = new Set(['ro', 'rw', 'rwr', 'rww', 'const']);
const writable = new Set(['rw', 'rwr', 'rww', 'wo']);

// Every sub-entry of the EDS as { index, subIndex, entry, name }.
function entriesOf(eds) {
  const list = [];
  for (const [key, object] of eds.entries()) {
    const index = parseInt(key, 16);
    if (object.objectType === 8 || object.objectType === 9) {
      for (let sub = 0; sub < 256; sub++) {
        const entry = object.at(sub);
        if (entry) {
          // node-canopen gives sub-index 0 of a CompactSubObj array access rw; CiA 306 (compact
          // storage) makes it ro, the number of entries. The EDS's meaning is used here.
          if (sub === 0 && object.compactSubObj) {
            entry.accessType = 'ro';
          }
          list.push({ index, subIndex: sub, entry, name: `${object.parameterName}: ${entry.parameterName}` });
        }
      }
    } else if (object.objectType === 7) {
      list.push({ index, subIndex: 0, entry: object, name: object.parameterName });
    }
  }
  return list;
}

function where(e) {
  return `${e.index.toString(16).toUpperCase().padStart(4, '0')}:${e.subIndex.toString(16).toUpperCase().padStart(2, '0')} ${e.name}`;
}

// The size the server indicated in its initiate response, or undefined (not indicated).
function indicatedSize(frame) {
  if (!frame || (frame.data[0] & 0xe0) !== 0x40) {
    return undefined;
  }
  const command = frame.data[0];
  if (!(command & 0x01)) {
    return undefined;
  }
  return command & 0x02 ? 4 - ((command >> 2) & 0x03) : frame.data.readUInt32LE(4);
}

async function readAll({ device, eds, sdo, nodeId }) {
  const { devices } = require('./devices');
  const unreachable = devices[device].unreachable || [];
  const problems = [];
  const notes = [];
  const reads = new Map();
  let count = 0;
  for (const e of entriesOf(eds)) {
    const access = String(e.entry.accessType).toLowerCase();
    const result = await sdo.upload(e.index, e.subIndex);
    if (unreachable.includes(e.index)) {
      if (result.abort !== 0x06020000) {
        problems.push(`${where(e)}: expected abort 0x06020000 (not reachable from the bus)`);
      }
      continue;
    }
    if (!readable.has(access)) {
      // CiA 301: reading a write-only object aborts 0x06010001.
      if (result.abort !== 0x06010001) {
        problems.push(`${where(e)} (wo): read gave ${result.abort ? hex(result.abort) : 'data'}, not abort 0x06010001`);
      }
      continue;
    }
    if (result.abort !== undefined) {
      problems.push(`${where(e)}: read aborted ${hex(result.abort)}`);
      continue;
    }
    count++;
    const data = Buffer.from(result.data);
    reads.set(`${e.index}:${e.subIndex}`, data);
    const size = typeSize(e.entry.dataType);
    const indicated = indicatedSize(result.initiate);
    if (size !== undefined) {
      if (indicated === undefined) {
        // CiA 301: an expedited response without size indication carries an unspecified
        // number of bytes; the SOLO answers every expedited upload so (errata-solo P1).
        if (data.length < size) {
          problems.push(`${where(e)}: ${data.length} bytes without size indication, type has ${size}`);
        }
        notes.push(`${where(e)}: size not indicated (${data.length} bytes, type ${size})`);
      } else if (indicated !== size || data.length !== size) {
        problems.push(`${where(e)}: ${data.length} bytes (indicated ${indicated}), EDS type has ${size}`);
      }
    }
    if (access === 'const') {
      const text = e.entry.defaultValue;
      if (size !== undefined && typeRange(e.entry.dataType)) {
        const expected = evaluateDefault(text, nodeId);
        if (expected !== undefined && !encode(expected, size).equals(data.subarray(0, size))) {
          problems.push(`${where(e)}: const reads ${data.toString('hex')}, EDS default ${text}`);
        }
      } else if (size === undefined && text !== undefined) {
        if (data.toString('latin1') !== String(text)) {
          problems.push(`${where(e)}: const reads "${data.toString('latin1')}", EDS default "${text}"`);
        }
      }
    }
  }
  notes.unshift(`${count} entries read`);
  return { problems, notes, reads };
}

// Aborts a device may answer to a value its type and EDS limits allow but its own rules do
// not (CiA 301 leaves these to the object: COB-ID rules, PDO mapping, device state).
const valueRefusals = new Set([
  0x06090030, 0x06090031, 0x06090032, 0x06090036, 0x06040041, 0x06040042, 0x06040043, 0x06040047,
  0x08000020, 0x08000021, 0x08000022,
]);

async function writeLimits({ device, eds, sdo, reads }) {
  const { devices } = require('./devices');
  const config = devices[device];
  const problems = [];
  const notes = [];
  let written = 0;
  for (const e of entriesOf(eds)) {
    const access = String(e.entry.accessType).toLowerCase();
    if (!writable.has(access)) {
      continue;
    }
    if ((config.unreachable || []).includes(e.index)) {
      continue;
    }
    const reason = skipReason(device, e.index, e.subIndex);
    if (reason) {
      notes.push(`skipped ${where(e)}: ${reason}`);
      continue;
    }
    const size = typeSize(e.entry.dataType);
    const range = typeRange(e.entry.dataType);
    const original = reads ? reads.get(`${e.index}:${e.subIndex}`) : undefined;
    if (!range) {
      // Strings, DOMAIN and floating point: the value read is written back.
      if (original !== undefined) {
        const back = await sdo.download(e.index, e.subIndex, original);
        if (back.abort !== undefined && !valueRefusals.has(back.abort)) {
          problems.push(`${where(e)}: writing back its value aborted ${hex(back.abort)}`);
        }
        written++;
      }
      continue;
    }
    // node-canopen reads LowLimit/HighLimit with parseInt(x) || undefined, so a limit of 0
    // reads as no limit; for the types concerned the type's range then applies (a write below
    // 0 is then a value refusal, still checked to be one).
    const low = e.entry.lowLimit !== undefined ? BigInt(e.entry.lowLimit) : undefined;
    const high = e.entry.highLimit !== undefined ? BigInt(e.entry.highLimit) : undefined;
    const attempts = [];
    const atLimit = (value, explicit) => attempts.push({ value, bytes: encode(value, size), explicit });
    atLimit(low ?? range[0], low !== undefined);
    atLimit(high ?? range[1], high !== undefined);
    for (const a of attempts) {
      const r = await sdo.download(e.index, e.subIndex, a.bytes);
      if (r.abort === undefined) {
        continue;
      }
      if (a.explicit || !valueRefusals.has(r.abort)) {
        problems.push(`${where(e)}: writing ${a.value} (${a.explicit ? 'EDS limit' : 'type limit'}) aborted ${hex(r.abort)}`);
      }
    }
    // One past: below LowLimit 0x06090032, above HighLimit 0x06090031 (CiA 301 abort codes;
    // its general 0x06090030, "invalid value", is accepted too: the SOLO documents it for every
    // range violation, errata-solo P8);
    // beyond the type, one byte more than the type: 0x06070012 (length too high) or 0x06070010.
    const past = [];
    if (low !== undefined && low > range[0]) {
      past.push({ bytes: encode(low - 1n, size), expect: [0x06090032, 0x06090030], what: `${low - 1n} (below LowLimit)` });
    }
    if (high !== undefined && high < range[1]) {
      past.push({ bytes: encode(high + 1n, size), expect: [0x06090031, 0x06090030], what: `${high + 1n} (above HighLimit)` });
    }
    if (e.entry.dataType === 0x01) {
      past.push({ bytes: Buffer.from([2]), expect: [0x06090030], what: '2 (not a BOOLEAN)' });
    }
    if (!config.keepsLowBytes) past.push({ bytes: Buffer.concat([encode(0n, size), Buffer.from([0])]), expect: [0x06070012, 0x06070010], what: `${size + 1} bytes` });
    for (const p of past) {
      const r = await sdo.download(e.index, e.subIndex, p.bytes);
      if (!p.expect.includes(r.abort)) {
        problems.push(`${where(e)}: writing ${p.what} gave ${r.abort === undefined ? 'success' : hex(r.abort)}, expected ${p.expect.map((c) => hex(c)).join(' or ')}`);
      }
    }
    if (original !== undefined) {
      const back = await sdo.download(e.index, e.subIndex, original.subarray(0, size));
      if (back.abort !== undefined) {
        problems.push(`${where(e)}: restoring ${original.toString('hex')} aborted ${hex(back.abort)}`);
      }
    }
    written++;
  }
  notes.unshift(`${written} writable entries written`);
  return { problems, notes };
}

module.exports = { readAll, writeLimits, entriesOf, where };
