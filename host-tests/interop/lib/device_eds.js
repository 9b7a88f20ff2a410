// The EDS a device was built from, as a master tool would import it.
'use strict';

const path = require('node:path');
const { Eds } = require('canopen');

const repository = path.resolve(__dirname, '..', '..', '..');

const edsFiles = {
  example: 'targets/example/example.eds',
  solo: 'targets/solo/solo.eds',
  gra: 'targets/gefran/gra.eds',
  grn: 'targets/gefran/grn.eds',
  santeng: 'targets/santeng/santeng.eds',
  mseries: 'targets/mseries/mseries.eds',
};

// The one place the suite gets a device's EDS. It reads the repository's file today; it will
// read the output of `costa-slave --eds DEVICE` (the EDS the slave was built from, byte for
// byte) once the slave prints it, so that the master imports exactly what the slave answers.
function loadDeviceEds(device) {
  const file = edsFiles[device];
  if (!file) {
    throw new Error(`no EDS known for device ${device}`);
  }
  return Eds.fromFile(path.join(repository, file));
}

module.exports = { loadDeviceEds, devices: Object.keys(edsFiles) };
