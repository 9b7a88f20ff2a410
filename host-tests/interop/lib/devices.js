// What the suite knows of each device beyond its EDS: the node-id it runs at and the entries
// whose write is skipped, each with the reason (a write whose side effect would break the rest
// of the run, or that changes the node's identity on the bus).
'use strict';

// Skipped on every device: the store and restore commands (a "save" writes the slave's
// non-volatile memory, a "load" changes the values of the next reset, which the NMT test does).
const commonSkips = {
  '1010': 'store parameters: a save writes the non-volatile memory',
  '1011': 'restore default parameters: changes the values of the next reset',
};

const devices = {
  example: {
    nodeId: 5,
    skips: {
      '2002': 'a command: its values start actions of the example application',
      // CiA 304 narrows these below their types' ranges (host-tests/unit/srdo_test.cpp tests
      // every rule on the wire).
      '1301': 'SRDO 1 communication: direction 0..2, SCT and SRVT not 0, type 254, COB-IDs 0x101..0x180 odd/even',
      '1302': 'SRDO 2 communication: direction 0..2, SCT and SRVT not 0, type 254, COB-IDs 0x101..0x180 odd/even',
      '1381': 'SRDO 1 mapping: written only while SRDO 1 is not valid (0x1301:01 = 0), pairs of a normal and an inverted entry of the same size',
      '1382': 'SRDO 2 mapping: written only while SRDO 2 is not valid (0x1302:01 = 0), pairs of a normal and an inverted entry of the same size',
    },
  },
  solo: {
    nodeId: 5,
    skips: {
      '3009': 'PWM frequency: written in kHz, read in Hz (errata-solo D8), so the EDS limits are the read side',
      '3001': 'the node-id (Set Device Address)',
      '3014': 'reset factory: restores and restarts the controller',
      '3026': 'UART baud rate',
      '302C': 'the CAN bit rate',
    },
  },
  gra: {
    nodeId: 5,
    // 0x1800:01 is ro on the Gefran: the TPDO cannot be invalidated, so it cannot be remapped.
    fixedPdos: 'TPDO COB-ID read-only (the GRA/GRN have one static TPDO)',
    skips: {
      '2101': 'zero points: below the full scale of the present resolution, not the EDS limit (errata-gefran E4)',
      '5999sub1': 'the CAN bit rate',
      '5999sub2': 'the node-id',
      '5999sub3': 'store LSS parameters: writes the non-volatile memory',
    },
  },
  grn: {
    nodeId: 5,
    fixedPdos: 'TPDO COB-ID read-only (the GRA/GRN have one static TPDO)',
    skips: {
      '2101': 'zero points: below the full scale of the present resolution, not the EDS limit (errata-gefran E4)',
      '5999sub1': 'the CAN bit rate',
      '5999sub2': 'the node-id',
      '5999sub3': 'store LSS parameters: writes the non-volatile memory',
    },
  },
  santeng: {
    nodeId: 5,
    // A write longer than a number stores its low bytes (errata-santeng W3), so "one byte more"
    // is accepted by design.
    keepsLowBytes: true,
    // 0x5000-0x5003 are in the EDS (stored configuration) but abort 0x06020000 on the bus
    // (errata-santeng D13).
    unreachable: [0x5000, 0x5001, 0x5002, 0x5003],
    skips: {
      '2017': 'save configuration: any value writes the non-volatile memory',
    },
  },
  mseries: {
    nodeId: 5,
    fixedPdos: 'PDO COB-IDs read-only (errata-m-series D8: the COB-ID is 0x180/0x200 + node-id)',
    // A consumer timeout is an alarm: heartbeat state 04, no EMCY (errata-m-series W6, W10).
    consumerTimeoutState: 0x04,
    skips: {
      '2614': 'data save flag: writes the non-volatile memory',
      '2615': 'device location: the node-id',
    },
  },
};

function skipReason(device, index, subIndex) {
  if (index >= 0x1400 && index <= 0x1bff) {
    return 'PDO parameters: writes follow the CiA 301 procedure (PDO invalid, mapping count 0 first), exercised by the PDO test';
  }
  const hex4 = index.toString(16).toUpperCase().padStart(4, '0');
  const own = devices[device].skips;
  return (
    own[`${hex4}sub${subIndex}`] || own[hex4] || commonSkips[`${hex4}sub${subIndex}`] || commonSkips[hex4]
  );
}

module.exports = { devices, skipReason };
