// CiA 301 basic data types as the suite needs them: sizes, ranges, little-endian encoding.
'use strict';

// Data type index (CiA 301 table 44) -> [size in bytes, signed]; types without a fixed size
// (strings, DOMAIN) are absent.
const fixedTypes = {
  0x01: [1, false], // BOOLEAN
  0x02: [1, true], // INTEGER8
  0x03: [2, true], // INTEGER16
  0x04: [4, true], // INTEGER32
  0x05: [1, false], // UNSIGNED8
  0x06: [2, false], // UNSIGNED16
  0x07: [4, false], // UNSIGNED32
  0x08: [4, null], // REAL32
  0x0c: [6, null], // TIME_OF_DAY
  0x0d: [6, null], // TIME_DIFFERENCE
  0x10: [3, true], // INTEGER24
  0x11: [8, null], // REAL64
  0x12: [5, true], // INTEGER40
  0x13: [6, true], // INTEGER48
  0x14: [7, true], // INTEGER56
  0x15: [8, true], // INTEGER64
  0x16: [3, false], // UNSIGNED24
  0x18: [5, false], // UNSIGNED40
  0x19: [6, false], // UNSIGNED48
  0x1a: [7, false], // UNSIGNED56
  0x1b: [8, false], // UNSIGNED64
};

function typeSize(dataType) {
  const t = fixedTypes[dataType];
  return t ? t[0] : undefined;
}

// [min, max] as BigInt for integer types (BOOLEAN 0..1), undefined for others.
function typeRange(dataType) {
  if (dataType === 0x01) {
    return [0n, 1n];
  }
  const t = fixedTypes[dataType];
  if (!t || t[1] === null) {
    return undefined;
  }
  const bits = BigInt(t[0] * 8);
  return t[1] ? [-(1n << (bits - 1n)), (1n << (bits - 1n)) - 1n] : [0n, (1n << bits) - 1n];
}

function encode(value, size) {
  const bytes = Buffer.alloc(size);
  let v = BigInt.asUintN(size * 8, BigInt(value));
  for (let i = 0; i < size; i++) {
    bytes[i] = Number(v & 0xffn);
    v >>= 8n;
  }
  return bytes;
}

function decode(bytes, signed) {
  let v = 0n;
  for (let i = bytes.length - 1; i >= 0; i--) {
    v = (v << 8n) | BigInt(bytes[i]);
  }
  return signed ? BigInt.asIntN(bytes.length * 8, v) : v;
}

function isSigned(dataType) {
  const t = fixedTypes[dataType];
  return !!(t && t[1]);
}

// A DefaultValue of the EDS as a number, with $NODEID replaced (CiA 306: "$NODEID+0x180").
function evaluateDefault(text, nodeId) {
  if (text === undefined || text === '') {
    return undefined;
  }
  const terms = String(text).replace(/\$NODEID/gi, String(nodeId)).split('+');
  let sum = 0n;
  for (const term of terms) {
    const t = term.trim();
    if (!/^-?(0x[0-9a-f]+|0[0-7]*|[1-9][0-9]*)$/i.test(t)) {
      return undefined;
    }
    const negative = t.startsWith('-');
    const digits = negative ? t.slice(1) : t;
    let v = /^0[0-7]+$/.test(digits) ? BigInt('0o' + digits.slice(1)) : BigInt(digits);
    sum += negative ? -v : v;
  }
  return sum;
}

module.exports = { typeSize, typeRange, encode, decode, isSigned, evaluateDefault };
