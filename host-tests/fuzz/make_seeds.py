#!/usr/bin/env python3
"""Writes the fuzzers' seed corpus: every conformance transcript turned into the fuzz input
encoding (host-tests/fuzz/fuzz_events.hpp, docs/fuzzing.md), plus a few hand-written inputs per
device for what no transcript does (power cycles over stored parameters, a storage power cut,
the CAN controller refusing frames, LSS from no node-id).

    make_seeds.py TRANSCRIPT_DIR OUTPUT_DIR

OUTPUT_DIR/<device>/<transcript name>.bin for the device each transcript names, and
OUTPUT_DIR/<device>/synthetic-*.bin. A transcript's `rx` frames become frame events, `wait`
becomes wait events, `sim` commands hall chip events; `tx`, `silence` and `ignore` say what the
device must send, which the fuzzer does not check (the transcript tests do), so they are left out.
The header is the transcript's node-id, given explicitly, as the in-process transcript tests do.
"""

import math
import pathlib
import shutil
import struct
import sys

DEVICES = ("example", "solo", "gra", "grn")

WAIT_MILLISECONDS = 0x41
FIRST_SHORT_WAIT = 0x44  # 0x45..0x7F: 1..59 ms
LONGEST_SHORT_WAIT = 0x7F - FIRST_SHORT_WAIT
REFUSE_FRAMES = 0x80
ACCEPT_FRAMES = 0x81
BUS_OFF = 0x85
BUS_OFF_RECOVERED = 0x86
POWER_CYCLE = 0x87
STORAGE_POWER_CUT = 0x88
HALL_READINGS = 0x89
HALL_FAULTS = 0x8A
OWN_SDO_REQUEST = 0xC0
WAIT_FOR_DEADLINE = 0x43
HALL_FAULT_BITS = {"chip1": 0x01, "chip2": 0x02, "magnet": 0x80}


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


def raw_from_degrees(degrees):
    turns = degrees / 360.0
    turns -= math.trunc(turns)
    if turns < 0:
        turns += 1.0
    return int(turns * 16384 + 0.5) % 16384


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


def convert(path):
    """Returns (device, seed bytes) of one transcript."""
    device = None
    node_id = 1
    events = b""
    faults = 0
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
            if rest[0] == "raw":
                chips = [int(rest[1]), int(rest[2])]
            elif rest[0] == "angle":
                chips = [raw_from_degrees(float(rest[1]))] * 2
            elif rest[0] == "fault":
                bit = HALL_FAULT_BITS[rest[1]]
                faults = faults | bit if rest[2] == "on" else faults & ~bit
                events += bytes([HALL_FAULTS, faults])
                continue
            else:
                raise SeedError(f"{where}: unknown sim command '{rest[0]}'")
            events += bytes([HALL_READINGS]) + struct.pack("<HH", *chips)
        elif keyword not in ("tx", "silence", "ignore"):
            raise SeedError(f"{where}: unknown keyword '{keyword}'")
    if device not in DEVICES:
        raise SeedError(f"{path}: device '{device}' is not fuzzed")
    return device, bytes([node_id]) + events


SAVE_ALL = sdo([0x23, 0x10, 0x10, 0x01, 0x73, 0x61, 0x76, 0x65])  # 0x1010:01 = "save"
LOAD_ALL = sdo([0x23, 0x11, 0x10, 0x01, 0x6C, 0x6F, 0x61, 0x64])  # 0x1011:01 = "load"
HEARTBEAT_100MS = sdo([0x2B, 0x17, 0x10, 0x00, 0x64, 0x00, 0x00, 0x00])
NMT_START_ALL = frame_event(0x000, 2, [0x01, 0x00])
LSS_CONFIGURATION = frame_event(0x7E5, 8, [0x04, 0x01, 0, 0, 0, 0, 0, 0])
LSS_NODE_ID_5 = frame_event(0x7E5, 8, [0x11, 0x05, 0, 0, 0, 0, 0, 0])
LSS_STORE = frame_event(0x7E5, 8, [0x17, 0, 0, 0, 0, 0, 0, 0])
LSS_WAITING = frame_event(0x7E5, 8, [0x04, 0x00, 0, 0, 0, 0, 0, 0])


def synthetic(device):
    """Hand-written inputs: header 0 (the device's own node-id) unless said otherwise."""
    seeds = {
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
    }
    if device != "solo":
        # No node-id at power-on: LSS gives it one and stores it; a power cycle keeps it.
        seeds["lss-unconfigured"] = (bytes([0xFF, WAIT_FOR_DEADLINE]) + LSS_CONFIGURATION
                                     + LSS_NODE_ID_5 + LSS_STORE + LSS_WAITING
                                     + bytes([POWER_CYCLE]) + wait_event(10))
    if device == "solo":
        # The device address 0x3001 is kept as soon as it is written (no store command).
        seeds["device-address"] = (bytes([0]) + sdo([0x23, 0x01, 0x30, 0x00, 5, 0, 0, 0])
                                   + bytes([POWER_CYCLE]) + wait_event(20))
    return seeds


def main(argv):
    if len(argv) != 3:
        print("usage: make_seeds.py TRANSCRIPT_DIR OUTPUT_DIR", file=sys.stderr)
        return 2
    transcripts = pathlib.Path(argv[1])
    output = pathlib.Path(argv[2])
    counts = {device: 0 for device in DEVICES}
    for device in DEVICES:
        shutil.rmtree(output / device, ignore_errors=True)  # no seed of a removed transcript
    try:
        for path in sorted(transcripts.rglob("*.transcript")):
            device, seed = convert(path)
            target = output / device / (path.stem + ".bin")
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(seed)
            counts[device] += 1
    except (SeedError, ValueError, IndexError, KeyError) as error:
        print(f"make_seeds.py: {error}", file=sys.stderr)
        return 1
    for device in DEVICES:
        for name, seed in synthetic(device).items():
            target = output / device / f"synthetic-{name}.bin"
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(seed)
            counts[device] += 1
    print("fuzz seeds: " + ", ".join(f"{device} {count}" for device, count in counts.items()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
