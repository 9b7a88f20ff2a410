#!/usr/bin/env python3
"""The test device_lists: every consumer of the device list has every device of it, no more, in
its order. The list is targets/devices.cmake (--devices: what CMake read from it) and its C++
twin targets/devices.hpp; a device missing from either, or from a consumer, fails here with
what is missing where.

    check_device_lists.py --root SRC --build BUILD --devices a,b,... --costa-slave EXE
                          --fuzz-replay EXE --fuzz-dictionary EXE --seeds DIR
                          --generator GEN --ctest EXE

Compared with the list:
  * tools/devices (the shell tools' reading of targets/devices.cmake), tools/fuzz --list-devices,
    tools/footprint --list-devices;
  * costa-slave --list-devices and costa_fuzz_replay --list-devices (the C++ list);
  * the seed directories (BUILD/host-tests/fuzz/seeds/<device>/, each with seeds), a libFuzzer
    dictionary per device, the ctest tests fuzz_replay_<device>;
  * the firmware images costa-<device>-firmware of a Cortex-M4 tree and the libFuzzer targets
    costa_fuzz_<device> of a COSTA_FUZZ tree: both trees are configured (not built) below
    BUILD/device-lists/, and their build targets listed.
"""

import argparse
import os
import re
import subprocess
import sys


def run(command, **kwargs):
    """The standard output of a command that must succeed."""
    result = subprocess.run(command, capture_output=True, text=True, **kwargs)
    if result.returncode != 0:
        raise RuntimeError("%s failed (status %d):\n%s%s" % (
            " ".join(command), result.returncode, result.stdout, result.stderr))
    return result.stdout


def lines(text):
    return [line for line in text.splitlines() if line.strip()]


class Checker:
    def __init__(self, devices):
        self.devices = devices
        self.problems = []

    def same_list(self, what, names):
        """`names` must be the device list, in order."""
        if names != self.devices:
            missing = [device for device in self.devices if device not in names]
            extra = [name for name in names if name not in self.devices]
            detail = []
            if missing:
                detail.append("missing " + ", ".join(missing))
            if extra:
                detail.append("not listed: " + ", ".join(extra))
            if not detail:
                detail.append("another order")
            self.problems.append("%s: %s (%s; the list: %s)" % (
                what, " ".join(names), "; ".join(detail), " ".join(self.devices)))

    def has_each(self, what, present, pattern):
        """Every device's `pattern` % device must be in `present`."""
        missing = [device for device in self.devices if pattern % device not in present]
        if missing:
            self.problems.append("%s: no %s" % (
                what, ", ".join(pattern % device for device in missing)))


def configured_targets(source, directory, generator, options):
    """The build targets of a tree configured (not built) with `options`."""
    run(["cmake", "-S", source, "-B", directory, "-G", generator] + options)
    if "Ninja" in generator:
        listing = run(["ninja", "-C", directory, "-t", "targets", "all"])
        return {line.split(":", 1)[0].strip() for line in lines(listing)}
    listing = run(["cmake", "--build", directory, "--target", "help"])
    return {re.sub(r"^\.\.\. ", "", line).split(" ")[0] for line in lines(listing)}


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    for option in ("--root", "--build", "--devices", "--costa-slave", "--fuzz-replay",
                   "--fuzz-dictionary", "--seeds", "--generator", "--ctest"):
        parser.add_argument(option, required=True)
    options = parser.parse_args(argv)
    devices = [device for device in options.devices.split(",") if device]
    if not devices:
        print("error: the device list is empty", file=sys.stderr)
        return 1
    check = Checker(devices)
    root = options.root
    try:
        check.same_list("tools/devices", lines(run([os.path.join(root, "tools", "devices")])))
        check.same_list("tools/fuzz --list-devices",
                        lines(run([os.path.join(root, "tools", "fuzz"), "--list-devices"])))
        check.same_list("tools/footprint --list-devices",
                        lines(run([os.path.join(root, "tools", "footprint"), "--list-devices"])))
        check.same_list("costa-slave --list-devices (targets/devices.hpp)",
                        [line.split()[0] for line in
                         lines(run([options.costa_slave, "--list-devices"]))
                         if not line[0].isspace()])
        check.same_list("costa_fuzz_replay --list-devices (targets/devices.hpp)",
                        lines(run([options.fuzz_replay, "--list-devices"])))

        seeded = sorted(name for name in os.listdir(options.seeds)
                        if os.path.isdir(os.path.join(options.seeds, name))
                        and os.listdir(os.path.join(options.seeds, name)))
        check.same_list("seed directories in %s" % options.seeds,
                        [device for device in devices if device in seeded]
                        + [name for name in seeded if name not in devices])
        for device in devices:
            dictionary = run([options.fuzz_dictionary, device])
            if len(lines(dictionary)) < 2:
                check.problems.append("costa_fuzz_dictionary %s: empty" % device)
        tests = set(re.findall(r"Test +#\d+: (\S+)",
                               run([options.ctest, "--test-dir", options.build, "-N"])))
        check.has_each("ctest in %s" % options.build, tests, "fuzz_replay_%s")

        trees = os.path.join(options.build, "device-lists")
        firmware = configured_targets(root, os.path.join(trees, "cortex-m4"), options.generator, [
            "-DCMAKE_TOOLCHAIN_FILE=" + os.path.join(root, "tools", "cmake", "arm-none-eabi.cmake"),
            "-DCOSTA_ARM_CPU=cortex-m4", "-DCMAKE_BUILD_TYPE=MinSizeRel"])
        check.has_each("firmware tree (Cortex-M4)", firmware, "costa-%s-firmware")
        fuzz = configured_targets(root, os.path.join(trees, "fuzz"), options.generator, [
            "-DCMAKE_C_COMPILER=clang-14", "-DCMAKE_CXX_COMPILER=clang++-14", "-DCOSTA_FUZZ=ON",
            "-DCMAKE_BUILD_TYPE=RelWithDebInfo"])
        check.has_each("fuzz tree (tools/fuzz)", fuzz, "costa_fuzz_%s")
    except (RuntimeError, OSError) as error:
        check.problems.append(str(error))
    if check.problems:
        for problem in check.problems:
            print("device list: " + problem, file=sys.stderr)
        return 1
    print("every consumer has the %d devices of targets/devices.cmake: %s"
          % (len(devices), " ".join(devices)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
