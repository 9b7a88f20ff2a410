#!/usr/bin/env python3
"""Writes the fuzzers' seed corpus: every conformance transcript turned into the fuzz input
encoding (host-tests/fuzz/fuzz_events.hpp, docs/fuzzing.md), plus a few hand-written inputs per
device for what no transcript does (power cycles over stored parameters, a storage power cut,
the CAN controller refusing frames, LSS from no node-id).

    make_seeds.py --devices DEVICE,... TRANSCRIPT_DIR OUTPUT_DIR

--devices is the device list (targets/devices.cmake). OUTPUT_DIR/<device>/<transcript
name>.bin for the device each transcript names, and OUTPUT_DIR/<device>/synthetic-*.bin for
every device. A transcript's `rx` frames become frame events, `wait` becomes wait events, `sim`
commands simulation command events (0x89, the command's text); `tx`, `silence` and `ignore` say
what the device must send, which the fuzzer does not check (the transcript tests do), so they
are left out. The header is the transcript's node-id, given explicitly, as the in-process
transcript tests do.
"""

import argparse
import pathlib
import shutil
import sys

WAIT_MILLISECONDS = 0x41
FIRST_SHORT_WAIT = 0x44  # 0x45..0x7F: 1..59 ms
LONGEST_SHORT_WAIT = 0x7F - FIRST_SHORT_WAIT
REFUSE_FRAMES = 0x80
ACCEPT_FRAMES = 0x81
BUS_OFF = 0x85
BUS_OFF_RECOVERED = 0x86
POWER_CYCLE = 0x87
STORAGE_POWER_CUT = 0x88
ENTRY_DOWNLOAD = 0x8C
SIMULATE = 0x89
LONGEST_COMMAND = 0xFF
OWN_SDO_REQUEST = 0xC0
WAIT_FOR_DEADLINE = 0x43


class SeedError(Exception):
    pass


def frame_event(can_id, dlc, data, rtr=False, extended=False):
    op = dlc | (0x10 if rtr else 0) | (0x20 if extended else 0)
    event = bytes([op]) + can_id.to_bytes(4 if extended else 2, "little")
    return event if rtr else event + bytes(data[: min(dlc, 8)])


def wait_event(milliseconds):
    out = b""
    while milliseconds > 0:
        if milliseconds <= LONGEST_SHORT_WAIT:
            return out + bytes([FIRST_SHORT_WAIT + milliseconds])
        step = min(milliseconds, 0xFFFF)
        out += bytes([WAIT_MILLISECONDS]) + step.to_bytes(2, "little")
        milliseconds -= step
    return out


def sdo(data):
    return bytes([OWN_SDO_REQUEST]) + bytes(data)


def simulate(command, where):
    """A simulation command event: its length, then its text."""
    text = command.encode()
    if not text or len(text) > LONGEST_COMMAND:
        raise SeedError(f"{where}: a sim command of 1..{LONGEST_COMMAND} bytes")
    return bytes([SIMULATE, len(text)]) + text


def parse_frame(words, where):
    if len(words) < 2:
        raise SeedError(f"{where}: expected '<id> [<dlc>] <bytes>'")
    extended = len(words[0]) > 3
    can_id = int(words[0], 16)
    dlc = int(words[1].strip("[]"))
    if len(words) == 3 and words[2] == "RTR":
        return frame_event(can_id, dlc, b"", rtr=True, extended=extended)
    data = bytes(int(byte, 16) for byte in words[2:])
    if len(data) != dlc:
        raise SeedError(f"{where}: length [{dlc}] but {len(data)} data bytes")
    return frame_event(can_id, dlc, data, extended=extended)


def convert(path, devices):
    """Returns (device, seed bytes) of one transcript."""
    device = None
    node_id = 1
    events = b""
    for number, line in enumerate(path.read_text().splitlines(), 1):
        words = line.split("#", 1)[0].split()
        if not words:
            continue
        where = f"{path}:{number}"
        keyword, rest = words[0], words[1:]
        if keyword == "device":
            device = rest[0]
        elif keyword == "node-id":
            node_id = int(rest[0])
        elif keyword == "rx":
            events += parse_frame(rest, where)
        elif keyword == "wait":
            events += wait_event(int(rest[0]))
        elif keyword == "sim":
            events += simulate(" ".join(rest), where)
        elif keyword not in ("tx", "silence", "ignore"):
            raise SeedError(f"{where}: unknown keyword '{keyword}'")
    if device not in devices:
        raise SeedError(f"{path}: device '{device}' is not in the device list")
    return device, bytes([node_id]) + events


SAVE_ALL = sdo([0x23, 0x10, 0x10, 0x01, 0x73, 0x61, 0x76, 0x65])  # 0x1010:01 = "save"
LOAD_ALL = sdo([0x23, 0x11, 0x10, 0x01, 0x6C, 0x6F, 0x61, 0x64])  # 0x1011:01 = "load"
HEARTBEAT_100MS = sdo([0x2B, 0x17, 0x10, 0x00, 0x64, 0x00, 0x00, 0x00])
NMT_START_ALL = frame_event(0x000, 2, [0x01, 0x00])
LSS_CONFIGURATION = frame_event(0x7E5, 8, [0x04, 0x01, 0, 0, 0, 0, 0, 0])
LSS_NODE_ID_5 = frame_event(0x7E5, 8, [0x11, 0x05, 0, 0, 0, 0, 0, 0])
LSS_STORE = frame_event(0x7E5, 8, [0x17, 0, 0, 0, 0, 0, 0, 0])
LSS_WAITING = frame_event(0x7E5, 8, [0x04, 0x00, 0, 0, 0, 0, 0, 0])


def synthetic():
    """Hand-written inputs, the same for every device: header 0 (the device's own node-id)
    unless said otherwise."""
    # Writes of 5 to entries across the dictionary (0x8C), then a power cycle: what a device that
    # keeps parameters as they are written (NodeSettings::saveParametersOnWrite) loads again.
    writes = b"".join(bytes([ENTRY_DOWNLOAD, entry, 5, 0, 0, 0]) for entry in range(10, 250, 30))
    return {
        "power-on": bytes([0]),
        # Parameters saved, then loaded after a power cycle, then "restore defaults".
        "store-power-cycle": bytes([0]) + HEARTBEAT_100MS + SAVE_ALL + bytes([POWER_CYCLE])
        + wait_event(250) + LOAD_ALL + bytes([POWER_CYCLE, WAIT_FOR_DEADLINE]),
        # The power fails 40 bytes into a save; the device restarts and saves again.
        "storage-power-cut": bytes([0]) + HEARTBEAT_100MS + bytes([STORAGE_POWER_CUT, 40, 0])
        + SAVE_ALL + SAVE_ALL + bytes([POWER_CYCLE]) + wait_event(150),
        # The controller refuses frames for a while, then goes bus-off and recovers.
        "controller": bytes([0]) + bytes([REFUSE_FRAMES]) + HEARTBEAT_100MS + NMT_START_ALL
        + wait_event(350) + bytes([ACCEPT_FRAMES, BUS_OFF]) + wait_event(120)
        + bytes([BUS_OFF_RECOVERED]) + wait_event(120),
        # No node-id at power-on: LSS gives it one and stores it; a power cycle keeps it. (A
        # device without LSS starts with a node-id of its own.)
        "lss-unconfigured": bytes([0xFF, WAIT_FOR_DEADLINE]) + LSS_CONFIGURATION + LSS_NODE_ID_5
        + LSS_STORE + LSS_WAITING + bytes([POWER_CYCLE]) + wait_event(10),
        "writes-power-cycle": bytes([0]) + writes + bytes([POWER_CYCLE]) + wait_event(20),
        # TIME on 0x100 (consumed where 0x1012 says so): a time of day, a wrong length, one past
        # midnight, then a day's rollover.
        "time": bytes([0]) + frame_event(0x100, 6, [0x10, 0x27, 0, 0, 0x2C, 0x01])
        + frame_event(0x100, 5, [0x10, 0x27, 0, 0, 0x2C])
        + frame_event(0x100, 6, [0x00, 0x5C, 0x26, 0x05, 0x2C, 0x01])
        + frame_event(0x100, 6, [0xFF, 0x5B, 0x26, 0x05, 0x2C, 0x01]) + wait_event(5),
        # Other nodes' emergencies (consumed where 0x1028 lists them), one of 7 bytes.
        "emcy-consumer": bytes([0]) + frame_event(0x082, 8, [0x10, 0x81, 0x11, 0, 0, 0, 0, 0])
        + frame_event(0x083, 7, [0, 0, 0, 0, 0, 0, 0])
        + frame_event(0x084, 8, [0x20, 0x81, 0x11, 0, 0, 0, 0, 0]),
        # An additional SDO server (where 0x1201 exists) on 0x681/0x6C1: a segmented upload on
        # it and one on the default server at once, a change of its CAN-ID refused while valid,
        # then its requests not valid in the middle of a transfer.
        "sdo-servers": bytes([0]) + sdo([0x23, 0x01, 0x12, 0x01, 0x81, 0x06, 0, 0])
        + sdo([0x23, 0x01, 0x12, 0x02, 0xC1, 0x06, 0, 0])
        + frame_event(0x681, 8, [0x40, 0x08, 0x10, 0, 0, 0, 0, 0])
        + sdo([0x40, 0x08, 0x10, 0, 0, 0, 0, 0])
        + frame_event(0x681, 8, [0x60, 0, 0, 0, 0, 0, 0, 0]) + sdo([0x60, 0, 0, 0, 0, 0, 0, 0])
        + sdo([0x23, 0x01, 0x12, 0x01, 0x82, 0x06, 0, 0])
        + frame_event(0x681, 8, [0xA4, 0x08, 0x10, 0, 0x7F, 0, 0, 0])
        + sdo([0x23, 0x01, 0x12, 0x01, 0x81, 0x06, 0, 0x80])
        + frame_event(0x681, 8, [0x70, 0, 0, 0, 0, 0, 0, 0]) + wait_event(1500),
        # The global fail-safe command (CiA 304), then one with data and one remote frame.
        "gfc": bytes([0]) + frame_event(0x001, 0, []) + frame_event(0x001, 1, [0])
        + frame_event(0x001, 0, [], rtr=True),
        # SRDO 2 of the example (0x103/0x104) after the master validated the configuration and
        # started the node: a good pair, then a bad inversion.
        "srdo": bytes([0])
        + frame_event(0x601, 8, [0x2F, 0xFE, 0x13, 0, 0xA5, 0, 0, 0])
        + frame_event(0x000, 2, [0x01, 0x00])
        + frame_event(0x103, 4, [0x11, 0x22, 0x33, 0x44])
        + frame_event(0x104, 4, [0xEE, 0xDD, 0xCC, 0xBB]) + wait_event(50)
        + frame_event(0x103, 4, [0x11, 0x22, 0x33, 0x44])
        + frame_event(0x104, 4, [0xEE, 0xDD, 0xCC, 0xBC]) + wait_event(200),
    }


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--devices", required=True, help="the device list, comma-separated")
    parser.add_argument("transcripts", type=pathlib.Path, help="the transcript directory")
    parser.add_argument("output", type=pathlib.Path, help="the seed directory")
    options = parser.parse_args(argv[1:])
    devices = [device for device in options.devices.split(",") if device]
    transcripts = options.transcripts
    output = options.output
    counts = {device: 0 for device in devices}
    for device in devices:
        shutil.rmtree(output / device, ignore_errors=True)  # no seed of a removed transcript
    try:
        for path in sorted(transcripts.rglob("*.transcript")):
            device, seed = convert(path, devices)
            target = output / device / (path.stem + ".bin")
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(seed)
            counts[device] += 1
    except (SeedError, ValueError, IndexError, KeyError) as error:
        print(f"make_seeds.py: {error}", file=sys.stderr)
        return 1
    for device in devices:
        for name, seed in synthetic().items():
            target = output / device / f"synthetic-{name}.bin"
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(seed)
            counts[device] += 1
    print("fuzz seeds: " + ", ".join(f"{device} {count}" for device, count in counts.items()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
