#!/usr/bin/env python3
"""Net instructions per hot-path operation (host-tests/benchmarks/hot_paths.hpp).

    hot_paths.py callgrind OPERATIONS.tsv DUMP_DIR   from costa_hot_paths_callgrind (x86-64)
    hot_paths.py qemu REPORT                         from costa-hot-paths.elf under QEMU

Each prints one line per operation, tab-separated: key, net instructions (one decimal), label.

The rule: gross = instructions of one run, the measuring loop included; `empty` is the gross
of the empty operation (the loop alone, and on Cortex-M the two timer reads spread over the
batch), `idle` the gross of one idle processing cycle. Then
    net = (gross - empty) - request frames x (idle - empty)
and the idle row is (idle - empty).

callgrind: OPERATIONS.tsv is the program's output (key, label, runs, request frames), DUMP_DIR
holds one callgrind.out.N per operation, named by CALLGRIND_DUMP_STATS_AT(key); gross =
totals / runs.

qemu: the report of costa-hot-paths.elf (hot_paths_firmware.cpp), run with `-icount shift=0`.
Instructions per SysTick tick come from the calibration loop (2 instructions per iteration):
the difference of the two calibration batches must be a whole number of instructions per tick
within 0.1 %, else the report is refused. gross = ticks x instructions per tick / runs.
"""
import glob
import re
import sys

EMPTY = "empty"
IDLE = "idle"


class Row:
    def __init__(self, key, label, frames, gross):
        self.key, self.label, self.frames, self.gross = key, label, frames, gross


def net(rows):
    """[(key, label, net)] of every row but the empty operation, in the rows' order."""
    by_key = {row.key: row for row in rows}
    for needed in (EMPTY, IDLE):
        if needed not in by_key:
            raise ValueError(f"no '{needed}' operation: the net rule needs it")
    empty = by_key[EMPTY].gross
    idle = by_key[IDLE].gross - empty
    result = []
    for row in rows:
        if row.key == EMPTY:
            continue
        value = idle if row.key == IDLE else (row.gross - empty) - row.frames * idle
        result.append((row.key, row.label, value))
    return result


def callgrind_totals(dump_dir):
    """{dump trigger: totals} of the callgrind.out.* files in `dump_dir`."""
    totals = {}
    for path in glob.glob(dump_dir + "/callgrind.out.*"):
        with open(path, encoding="utf-8") as dump:
            text = dump.read()
        trigger = re.search(r"^desc: Trigger: Client Request: (\S+)$", text, re.M)
        total = re.search(r"^totals: (\d+)", text, re.M)
        if trigger and total:
            totals[trigger.group(1)] = int(total.group(1))
    return totals


def from_callgrind(operations_tsv, dump_dir):
    totals = callgrind_totals(dump_dir)
    rows = []
    with open(operations_tsv, encoding="utf-8") as lines:
        for line in lines:
            if not line.strip():
                continue
            key, label, runs, frames = line.rstrip("\n").split("\t")
            if key not in totals:
                raise ValueError(f"no callgrind dump for {key}")
            rows.append(Row(key, label, int(frames), totals[key] / int(runs)))
    return net(rows)


def instructions_per_tick(calibrations):
    """Whole instructions per timer tick from [(iterations, ticks)] of the 2-instruction loop."""
    if len(calibrations) != 2:
        raise ValueError("the report needs exactly two calibration lines")
    (short_iterations, short_ticks), (long_iterations, long_ticks) = sorted(calibrations)
    ticks = long_ticks - short_ticks
    if ticks <= 0:
        raise ValueError("the calibration loop took no time: is -icount on?")
    ratio = 2 * (long_iterations - short_iterations) / ticks
    whole = round(ratio)
    if whole < 1 or abs(ratio - whole) > 0.001 * whole:
        raise ValueError(f"{ratio:.4f} instructions per tick is not a whole number: "
                         "run QEMU with -icount shift=0")
    return whole


def from_qemu(report_text):
    runs = None
    calibrations = []
    rows = []
    for line in report_text.splitlines():
        words = line.split()
        if not words:
            continue
        if words[0] == "error":
            raise ValueError("the firmware reported: " + " ".join(words[1:]))
        if words[0] == "hot-paths":
            runs = int(words[1])
        elif words[0] == "calibration":
            calibrations.append((int(words[1]), int(words[2])))
        elif words[0] == "op":
            rows.append((words[1], int(words[2]), int(words[3])))
    if runs is None or not rows:
        raise ValueError("not a complete hot-paths report")
    per_tick = instructions_per_tick(calibrations)
    return net([Row(key, key, frames, ticks * per_tick / runs) for key, frames, ticks in rows])


def print_rows(rows):
    for key, label, value in rows:
        print(f"{key}\t{value:.1f}\t{label}")


def main(argv):
    try:
        if len(argv) == 3 and argv[0] == "callgrind":
            print_rows(from_callgrind(argv[1], argv[2]))
            return 0
        if len(argv) == 2 and argv[0] == "qemu":
            with open(argv[1], encoding="utf-8") as report:
                print_rows(from_qemu(report.read()))
            return 0
    except (OSError, ValueError) as error:
        print(f"hot_paths.py: {error}", file=sys.stderr)
        return 1
    print("usage:\n" + "\n".join(__doc__.strip().splitlines()[2:4]), file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
