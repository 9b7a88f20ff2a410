#!/usr/bin/env python3
"""The test slave_eds: `costa-slave --eds DEVICE` prints the EDS the device was built from,
byte for byte, and what it prints parses with the generator; `--list-devices` gives every device
its identity line.

    check_slave_eds.py --costa-slave EXE --generator DIR NAME=EDS [NAME=EDS ...]

NAME=EDS: each device and the EDS file its dictionary is generated from (what CMake knows).
"""

import argparse
import os
import subprocess
import sys
import tempfile


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--costa-slave", required=True)
    parser.add_argument("--generator", required=True, help="od/generator")
    parser.add_argument("devices", nargs="+", metavar="NAME=EDS")
    options = parser.parse_args(argv)
    failures = []

    for pair in options.devices:
        name, path = pair.split("=", 1)
        printed = subprocess.run([options.costa_slave, "--eds", name], capture_output=True)
        with open(path, "rb") as eds:
            expected = eds.read()
        if printed.returncode != 0 or printed.stdout != expected:
            failures.append("costa-slave --eds %s (status %d) differs from %s: %d bytes, "
                            "expected %d" % (name, printed.returncode, path,
                                             len(printed.stdout), len(expected)))
            continue
        with tempfile.TemporaryDirectory() as scratch:
            printed_path = os.path.join(scratch, name + ".eds")
            with open(printed_path, "wb") as out:
                out.write(printed.stdout)
            generated = subprocess.run(
                [sys.executable, "-B", os.path.join(options.generator, "costa_odgen.py"),
                 "--eds", printed_path, "--name", name, "--out-dir", scratch],
                capture_output=True, text=True)
            if generated.returncode != 0:
                failures.append("the generator refuses costa-slave --eds %s:\n%s" %
                                (name, generated.stderr))
        print("ok: costa-slave --eds %s is %s (%d bytes) and generates" %
              (name, path, len(expected)))

    unknown = subprocess.run([options.costa_slave, "--eds", "no-such-device"],
                             capture_output=True, text=True)
    if (unknown.returncode != 2 or unknown.stdout or len(unknown.stderr.splitlines()) != 1
            or "unknown device 'no-such-device'" not in unknown.stderr):
        failures.append("costa-slave --eds no-such-device: status %d, stdout %r, stderr %r "
                        "(expected status 2 and one line)" %
                        (unknown.returncode, unknown.stdout, unknown.stderr))

    listing = subprocess.run([options.costa_slave, "--list-devices"], capture_output=True,
                             text=True, check=True).stdout.splitlines()
    for pair in options.devices:
        name = pair.split("=", 1)[0]
        rows = [i for i, line in enumerate(listing) if line.split()[:1] == [name]]
        identity = listing[rows[0] + 1] if rows and rows[0] + 1 < len(listing) else ""
        if not identity.startswith(" ") or not ("vendor-id 0x" in identity or
                                                "no identity object" in identity):
            failures.append("--list-devices shows no identity line for %s: %r" %
                            (name, identity))

    for failure in failures:
        print("FAIL: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
