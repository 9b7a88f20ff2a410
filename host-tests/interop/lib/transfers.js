// A segmented and a block transfer of the device's largest readable object.
'use strict';

const { entriesOf, where } = require('./dictionary');
const { hex } = require('./sdo');
const { skipReason } = require('./devices');

async function largest({ device, eds, sdo, reads }) {
  const problems = [];
  const notes = [];
  let biggest;
  for (const e of entriesOf(eds)) {
    const data = reads && reads.get(`${e.index}:${e.subIndex}`);
    if (data && (!biggest || data.length > biggest.data.length)) {
      biggest = { ...e, data };
    }
  }
  if (!biggest || biggest.data.length <= 4) {
    notes.push('skipped: no readable object longer than 4 bytes, so no segmented transfer');
    return { problems, notes };
  }
  notes.push(`largest: ${where(biggest)}, ${biggest.data.length} bytes`);
  const segmented = await sdo.upload(biggest.index, biggest.subIndex);
  if (segmented.abort !== undefined || (segmented.initiate.data[0] & 0x02) !== 0) {
    problems.push(`segmented upload: ${segmented.abort ? hex(segmented.abort) : 'answered expedited'}`);
  }
  const block = await sdo.upload(biggest.index, biggest.subIndex, { block: true });
  if (block.abort !== undefined) {
    problems.push(`block upload aborted ${hex(block.abort)}`);
  } else if (!Buffer.from(block.data).equals(Buffer.from(segmented.data))) {
    problems.push(`block upload ${Buffer.from(block.data).toString('hex')} != segmented ${Buffer.from(segmented.data).toString('hex')}`);
  }
  const access = String(biggest.entry.accessType).toLowerCase();
  if (!['rw', 'rww', 'rwr'].includes(access) || skipReason(device, biggest.index, biggest.subIndex)) {
    notes.push(`downloads skipped: ${where(biggest)} is ${access}`);
    return { problems, notes };
  }
  // The segmented download writes the value reversed, the block download the original back:
  // each read back shows that the write took place.
  const original = Buffer.from(biggest.data);
  const reversed = Buffer.from(original).reverse();
  for (const [mode, value] of [[{ block: false }, reversed], [{ block: true }, original]]) {
    const what = mode.block ? 'block download' : 'segmented download';
    const r = await sdo.download(biggest.index, biggest.subIndex, value, mode);
    if (r.abort !== undefined) {
      problems.push(`${what} aborted ${hex(r.abort)}`);
      continue;
    }
    const back = await sdo.upload(biggest.index, biggest.subIndex);
    if (back.abort !== undefined || !Buffer.from(back.data).equals(value)) {
      problems.push(`${what}: read back ${back.abort ? hex(back.abort) : Buffer.from(back.data).toString('hex')}`);
    }
  }
  return { problems, notes };
}

module.exports = { largest };
