#!/usr/bin/env python3
"""Compiles transcripts into C++ tables for the transcript replayer (replay_script.hpp).

    transcripts_to_cpp.py --suite NAME --symbol kNameSuite --root DIR --output FILE.cpp
                          --devices DEVICE,... TRANSCRIPT...

Every transcript is parsed with exactly the rules of host-tests/support/transcript.cpp (the
parser the in-process and SocketCAN layers use): the same keywords, the same number syntax (as
C++ stream extraction reads it) and the same error messages. A transcript that does not parse,
or names a device that is not in --devices (the device list, targets/devices.cmake), stops the
build with "error: PATH:LINE: MESSAGE".
The tables list the transcripts sorted by their path below --root, which is also their name in
the replay report.
"""

import argparse
import os
import sys

# The characters std::isspace accepts in the "C" locale; bytes.split() splits on the same.
SPACE = b" \t\n\v\f\r"

STEP_KINDS = {
    "rx": "StepKind::kReceive",
    "tx": "StepKind::kTransmit",
    "wait": "StepKind::kWait",
    "silence": "StepKind::kSilence",
    "sim": "StepKind::kSimulate",
}


class TranscriptError(Exception):
    """A transcript that does not parse; the message is "PATH:LINE: what"."""


def text(raw):
    """Bytes of a transcript as text for a message."""
    return raw.decode("utf-8", "backslashreplace")


def skip_space(raw, at):
    while at < len(raw) and raw[at] in SPACE:
        at += 1
    return at


def stream_integer(raw, bits, signed=True, base=10):
    """What `std::istringstream(raw) >> value` gives for an integer of `bits` bits: the value,
    or None when the extraction fails (no digits, or out of range)."""
    at = skip_space(raw, 0)
    negative = False
    if at < len(raw) and raw[at] in b"+-":
        negative = raw[at] == ord("-")
        at += 1
    digits = b"0123456789" if base == 10 else b"0123456789abcdefABCDEF"
    if base == 16 and raw[at:at + 2] in (b"0x", b"0X"):
        at += 2
    start = at
    while at < len(raw) and raw[at] in digits:
        at += 1
    if at == start:
        return None
    value = int(raw[start:at], base)
    if signed:
        value = -value if negative else value
        if not -(1 << (bits - 1)) <= value < (1 << (bits - 1)):
            return None
        return value
    if value >= 1 << bits:
        return None
    return (-value) % (1 << bits) if negative else value


def parse_hex(token, limit):
    """frame_text.cpp parseHex: 1..8 hex digits, at most `limit`."""
    if not token or len(token) > 8 or any(c not in b"0123456789abcdefABCDEF" for c in token):
        return None
    value = int(token, 16)
    return value if value <= limit else None


def parse_frame(rest):
    """frame_text.cpp parseFrame: (id, extended, rtr, dlc, data, wildcards) or a message."""
    tokens = rest.split()
    if len(tokens) < 2:
        return "expected '<id> [<dlc>] <bytes>'"
    extended = len(tokens[0]) > 3
    can_id = parse_hex(tokens[0], 0x1FFFFFFF if extended else 0x7FF)
    if can_id is None:
        return "bad identifier '%s'" % text(tokens[0])
    dlc_token = tokens[1]
    if (len(dlc_token) != 3 or dlc_token[0:1] != b"[" or dlc_token[2:3] != b"]"
            or dlc_token[1:2] < b"0" or dlc_token[1:2] > b"8"):
        return "bad length '%s' (expected [0]..[8])" % text(dlc_token)
    dlc = dlc_token[1] - ord("0")
    data = [0] * 8
    wildcards = 0
    rtr = len(tokens) == 3 and tokens[2] == b"RTR"
    if not rtr:
        if len(tokens) - 2 != dlc:
            return "length [%d] but %d data bytes" % (dlc, len(tokens) - 2)
        for i, byte in enumerate(tokens[2:]):
            if byte in (b"xx", b"XX"):
                wildcards |= 1 << i
                continue
            value = parse_hex(byte, 0xFF) if len(byte) == 2 else None
            if value is None:
                return "bad data byte '%s'" % text(byte)
            data[i] = value
    return (can_id, extended, rtr, dlc, data, wildcards)


def parse_transcript(content, path, devices):
    """transcript.cpp parseTranscript: a dict with device, node_id, steps and ignored; the
    device must be one of `devices`."""
    transcript = {"device": b"", "node_id": 1, "steps": [], "ignored": []}
    for number, raw in enumerate(content.split(b"\n"), start=1):
        line = raw.split(b"#", 1)[0]
        words = line.split()
        if not words:
            continue

        def fail(message, number=number):
            raise TranscriptError("%s:%d: %s" % (path, number, message))

        keyword = words[0]
        rest = line[line.index(keyword) + len(keyword):]
        step = {"line": number}
        if keyword == b"device":
            if rest.split():
                transcript["device"] = rest.split()[0]
            continue
        if keyword == b"node-id":
            node_id = stream_integer(rest, 32)
            if node_id is None or not 1 <= node_id <= 127:
                fail("node-id must be 1..127")
            transcript["node_id"] = node_id
            continue
        if keyword in (b"rx", b"tx"):
            frame = parse_frame(rest)
            if isinstance(frame, str):
                fail(frame)
            if keyword == b"rx" and frame[5] != 0:
                fail("'xx' is only allowed in expected (tx) frames")
            step["frame"] = frame
        elif keyword == b"wait":
            milliseconds = stream_integer(rest, 64)
            if milliseconds is None or milliseconds < 0:
                fail("wait needs a number of milliseconds")
            step["milliseconds"] = milliseconds
        elif keyword == b"silence":
            pass
        elif keyword == b"sim":
            command = rest.lstrip(b" ").rstrip(b" \t")
            if not command:
                fail("sim needs a command")
            step["command"] = command
        elif keyword == b"ignore":
            can_id = stream_integer(rest, 64, signed=False, base=16)
            if can_id is None or can_id > 0x7FF:
                fail("ignore needs an 11-bit CAN-ID in hex")
            if len(rest.split()) > 1:
                fail("ignore takes one CAN-ID (one line each)")
            transcript["ignored"].append(can_id)
            continue
        else:
            fail("unknown keyword '%s'" % text(keyword))
        step["kind"] = keyword.decode()
        transcript["steps"].append(step)
    if not transcript["device"]:
        raise TranscriptError("%s: no 'device' line" % path)
    device = text(transcript["device"])
    if device not in devices:
        raise TranscriptError("%s: device '%s' cannot be replayed (%s)"
                              % (path, device, ", ".join(devices)))
    transcript["device"] = device
    return transcript


def cpp_string(raw):
    """A C++ string literal with exactly the bytes of `raw`."""
    out = []
    for byte in raw:
        if byte in (ord('"'), ord("\\")):
            out.append("\\" + chr(byte))
        elif 0x20 <= byte < 0x7F:
            out.append(chr(byte))
        else:
            out.append("\\%03o" % byte)
    return '"' + "".join(out) + '"'


def cpp_step(step):
    can_id, extended, rtr, dlc, data, wildcards = step.get(
        "frame", (0, False, False, 0, [0] * 8, 0))
    frame = "{0x%X, {%s}, %d, %s, %s}" % (
        can_id, ", ".join("0x%02X" % byte for byte in data), dlc, "true" if rtr else "false",
        "true" if extended else "false")
    command = cpp_string(step["command"]) if "command" in step else "nullptr"
    return "    {%s, %d, 0x%02X, %s, %dU, %s}," % (
        STEP_KINDS[step["kind"]], step["line"], wildcards, frame, step.get("milliseconds", 0),
        command)


def generate(suite, symbol, scripts):
    """The C++ source of one suite; `scripts` is a sorted list of (name, transcript)."""
    lines = [
        "// Generated by host-tests/replay/transcripts_to_cpp.py from host-tests/transcripts/%s;"
        % suite,
        "// do not edit.",
        '#include "replay_script.hpp"',
        '#include "suites.hpp"',
        "",
        "namespace costa::replay {",
        "namespace {",
        "",
    ]
    rows = []
    for index, (name, transcript) in enumerate(scripts):
        steps, ignored = "nullptr", "nullptr"
        if transcript["steps"]:
            steps = "kSteps%d" % index
            lines.append("// %s" % name)
            lines.append("constexpr Step %s[] = {" % steps)
            lines.extend(cpp_step(step) for step in transcript["steps"])
            lines.append("};")
        if transcript["ignored"]:
            ignored = "kIgnored%d" % index
            lines.append("constexpr uint32_t %s[] = {%s};" % (
                ignored, ", ".join("0x%X" % can_id for can_id in transcript["ignored"])))
        lines.append("")
        rows.append("    {%s, %s, %d, %s, %d, %s, %d}," % (
            cpp_string(name.encode()), cpp_string(transcript["device"].encode()),
            transcript["node_id"],
            steps, len(transcript["steps"]), ignored, len(transcript["ignored"])))
    if rows:
        lines.append("constexpr Script kScripts[] = {")
        lines.extend(rows)
        lines.append("};")
        table = "kScripts"
    else:
        table = "nullptr"
    lines.extend([
        "",
        "}  // namespace",
        "",
        "extern const Suite %s = {%s, %s, %d};" % (symbol, cpp_string(suite.encode()), table,
                                                   len(rows)),
        "",
        "}  // namespace costa::replay",
        "",
    ])
    return "\n".join(lines)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--suite", required=True, help="the suite's name (its directory)")
    parser.add_argument("--symbol", required=True, help="C++ name of the Suite constant")
    parser.add_argument("--root", required=True, help="directory the script names are below")
    parser.add_argument("--output", required=True, help="the C++ file to write")
    parser.add_argument("--devices", required=True,
                        help="the devices a transcript may name, comma-separated")
    parser.add_argument("transcripts", nargs="*")
    options = parser.parse_args(argv)
    devices = [device for device in options.devices.split(",") if device]
    scripts = []
    try:
        for path in options.transcripts:
            with open(path, "rb") as file:
                content = file.read()
            name = os.path.relpath(path, options.root).replace(os.sep, "/")
            scripts.append((name, parse_transcript(content, path, devices)))
    except (TranscriptError, OSError) as error:
        print("error: %s" % error, file=sys.stderr)
        return 1
    scripts.sort(key=lambda script: script[0])
    source = generate(options.suite, options.symbol, scripts)
    with open(options.output, "w", encoding="utf-8") as file:
        file.write(source)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
