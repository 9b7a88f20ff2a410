// The EDS a device was built from, as a master tool would import it: what
// `costa-slave --eds DEVICE` prints (byte for byte the EDS of the slave's dictionary).
'use strict';

const { execFileSync } = require('node:child_process');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');
const { Eds } = require('canopen');
const { slavePath } = require('./slave');

// The devices costa-slave runs: the first word of each unindented line of --list-devices.
function listDevices() {
  const listing = execFileSync(slavePath(), ['--list-devices'], { encoding: 'utf8' });
  return listing
    .split('\n')
    .filter((line) => line.length > 0 && !/^\s/.test(line))
    .map((line) => line.split(/\s+/)[0]);
}

// The one place the suite gets a device's EDS: from the slave itself. node-canopen reads EDS
// files only, so the text goes through a temporary file.
function loadDeviceEds(device) {
  const text = execFileSync(slavePath(), ['--eds', device]);
  const directory = fs.mkdtempSync(path.join(os.tmpdir(), 'costa-eds-'));
  const file = path.join(directory, `${device}.eds`);
  try {
    fs.writeFileSync(file, text);
    return Eds.fromFile(file);
  } finally {
    fs.rmSync(directory, { recursive: true, force: true });
  }
}

module.exports = { loadDeviceEds, listDevices };
