#!/usr/bin/env python3
"""The budgets of tools/budgets.txt against measured numbers (tools/check-budgets runs it).

    budgets.py measure [--instructions NET.tsv] [--tree NAME=DIR]...
        prints the measured rows, one per line: row name, TAB, number. NET.tsv: the x86-64
        net instructions of the hot paths (tools/perf/x86-hot-paths writes it); DIR: a
        firmware build tree, whose rows are named NAME
    budgets.py check BUDGETS MEASURED
        prints the table of number against budget; exit status 1 when a number exceeds its
        budget, when a measured row has no budget or a budgeted row was not measured (each
        failing row is named); 2 when a file cannot be read or parsed
    budgets.py update BUDGETS MEASURED
        sets every budget of BUDGETS to its measured number and adds a row for every measured
        number without one (rows that were not measured are left as they are)

Rows (the lines of BUDGETS):
    instructions OPERATION BUDGET        x86-64 net instructions of a hot path (callgrind);
                                         the measured number is rounded to a whole one
    image TREE IMAGE FLASH RAM           bytes of the firmware image IMAGE of build-TREE/:
                                         flash = text + data, RAM = data + bss without the
                                         stack that the linker script reserves (_stack_size)
Their names: "instructions OPERATION", "TREE IMAGE flash", "TREE IMAGE RAM".

A tree's images are the device images (targets/firmware/costa-*.elf) and the footprint images
of configurations A and B (host-tests/benchmarks/costa-footprint-*.elf), named as
tools/footprint names them: "costa-solo-firmware.elf" is "solo". Test images (transcript
replay, hot-path counting) are not budgeted: their size is that of their test data.
"""
import glob
import math
import os
import subprocess
import sys

IMAGE_PATTERNS = ("targets/firmware/costa-*.elf", "host-tests/benchmarks/costa-footprint-*.elf")


class BudgetError(Exception):
    pass


def whole(number):
    """Rounded half up: 631.5 -> 632."""
    return int(math.floor(number + 0.5))


# --- measuring -------------------------------------------------------------------------------
def image_name(path):
    name = os.path.basename(path)[len("costa-"):-len(".elf")]
    return name[:-len("-firmware")] if name.endswith("-firmware") else name


def image_size(elf):
    """(flash, RAM) of an image, as tools/footprint measures them."""
    berkeley = subprocess.run(["arm-none-eabi-size", "-B", "-d", elf], check=True,
                              capture_output=True, text=True).stdout.splitlines()[1].split()
    text, data, bss = (int(field) for field in berkeley[:3])
    symbols = subprocess.run(["arm-none-eabi-nm", elf], check=True, capture_output=True,
                             text=True).stdout.splitlines()
    stack = next((int(line.split()[0], 16) for line in symbols if line.endswith(" _stack_size")),
                 0)
    return text + data, data + bss - stack


def measure(instructions, trees):
    """[(row name, number)]: the hot paths' instructions, then every image of every tree."""
    rows = []
    if instructions:
        with open(instructions, encoding="utf-8") as lines:
            for line in lines:
                key, value = line.split("\t")[:2]
                rows.append((f"instructions {key}", whole(float(value))))
    for tree, directory in trees:
        images = [path for pattern in IMAGE_PATTERNS
                  for path in sorted(glob.glob(os.path.join(directory, pattern)))]
        if not images:
            raise BudgetError(f"no firmware image in {directory}: build the tree first")
        for path in images:
            flash, ram = image_size(path)
            rows += [(f"{tree} {image_name(path)} flash", flash),
                     (f"{tree} {image_name(path)} RAM", ram)]
    return rows


# --- the budgets file ------------------------------------------------------------------------
def budget_rows(line, where):
    """[(row name, budget)] of one line of the budgets file."""
    words = line.split("#", 1)[0].split()
    if not words:
        return []
    try:
        if words[0] == "instructions" and len(words) == 3:
            return [(f"instructions {words[1]}", int(words[2]))]
        if words[0] == "image" and len(words) == 5:
            name = f"{words[1]} {words[2]}"
            return [(f"{name} flash", int(words[3])), (f"{name} RAM", int(words[4]))]
    except ValueError:
        pass
    raise BudgetError(f"{where}: not 'instructions OPERATION N' nor 'image TREE IMAGE FLASH RAM'")


def read_budgets(path):
    budgets = {}
    with open(path, encoding="utf-8") as lines:
        for number, line in enumerate(lines, 1):
            for name, budget in budget_rows(line, f"{path}:{number}"):
                if name in budgets:
                    raise BudgetError(f"{path}:{number}: a second budget for '{name}'")
                budgets[name] = budget
    return budgets


def read_measured(path):
    measured = []
    with open(path, encoding="utf-8") as lines:
        for number, line in enumerate(lines, 1):
            if not line.strip():
                continue
            try:
                name, value = line.rstrip("\n").split("\t")
                measured.append((name, int(value)))
            except ValueError:
                raise BudgetError(f"{path}:{number}: not 'ROW<TAB>NUMBER'") from None
    return measured


# --- checking --------------------------------------------------------------------------------
def check(budgets, measured):
    """(table lines, failures): every row with its number, budget and verdict, in the order of
    the budgets file, then what was measured without a budget."""
    values = dict(measured)
    lines = ["| row | measured | budget | verdict |", "|---|--:|--:|---|"]
    failures = []
    for name, budget in budgets.items():
        value = values.get(name)
        if value is None:
            lines.append(f"| {name} | — | {budget:,} | FAIL: not measured |")
            failures.append(f"{name}: has a budget but was not measured (not built?)")
            continue
        if value > budget:
            verdict = f"FAIL: {value - budget:,} over"
            failures.append(f"{name}: {value:,} exceeds its budget of {budget:,}")
        else:
            verdict = "ok" if value == budget else f"ok, {budget - value:,} under"
        lines.append(f"| {name} | {value:,} | {budget:,} | {verdict} |")
    for name, value in measured:
        if name not in budgets:
            lines.append(f"| {name} | {value:,} | — | FAIL: no budget |")
            failures.append(f"{name}: measured {value:,}, no budget in the budgets file")
    return lines, failures


def self_check(measured):
    """Problems of check() itself: budgets equal to `measured` must pass, and a budget of each
    kind (instructions, flash, RAM) lowered by one must fail, naming that row alone."""
    exact = dict(measured)
    problems = []
    if check(exact, measured)[1]:
        problems.append("budgets equal to the measured numbers do not pass")
    kinds = (lambda name: name.startswith("instructions "), lambda name: name.endswith(" flash"),
             lambda name: name.endswith(" RAM"))
    for is_kind in kinds:
        name = next((row for row, _ in measured if is_kind(row)), None)
        if name is None:
            continue
        lowered = dict(exact)
        lowered[name] -= 1
        failures = check(lowered, measured)[1]
        if len(failures) != 1 or not failures[0].startswith(name + ":"):
            problems.append(f"'{name}' lowered by one does not fail alone")
    return problems


def update(path, measured):
    """Sets the budgets of `path` to `measured`; returns the changed and added row names."""
    values = dict(measured)
    with open(path, encoding="utf-8") as lines:
        text = lines.read().splitlines()
    changed, known = [], set()
    for i, line in enumerate(text):
        words = line.split("#", 1)[0].split()
        rows = budget_rows(line, f"{path}:{i + 1}")
        if not rows:
            continue
        known.update(name for name, _ in rows)
        new = [values.get(name, budget) for name, budget in rows]
        if new != [budget for _, budget in rows]:
            changed += [name for (name, budget), value in zip(rows, new) if value != budget]
            words[-len(new):] = [str(value) for value in new]
            comment = line.split("#", 1)[1] if "#" in line else None
            text[i] = format_row(words) + (f"  #{comment}" if comment is not None else "")
    added = []
    for name, value in measured:
        if name in known:
            continue
        if name.startswith("instructions "):
            text.append(format_row(["instructions", name.split()[1], str(value)]))
            added.append(name)
        elif name.endswith(" flash"):
            tree, image = name.split()[:2]
            ram = values.get(f"{tree} {image} RAM", 0)
            text.append(format_row(["image", tree, image, str(value), str(ram)]))
            added += [name, f"{tree} {image} RAM"]
    with open(path, "w", encoding="utf-8") as out:
        out.write("\n".join(text) + "\n")
    return changed, added


def format_row(words):
    if words[0] == "instructions":
        return f"instructions {words[1]:<26} {words[2]:>7}"
    return f"image {words[1]:<25} {words[2]:<16} {words[3]:>7} {words[4]:>7}"


def main(argv):
    try:
        if argv[:1] == ["measure"]:
            instructions, trees, rest = None, [], argv[1:]
            while rest:
                if rest[0] == "--instructions" and len(rest) >= 2:
                    instructions, rest = rest[1], rest[2:]
                elif rest[0] == "--tree" and len(rest) >= 2 and "=" in rest[1]:
                    trees.append(tuple(rest[1].split("=", 1)))
                    rest = rest[2:]
                else:
                    raise BudgetError(f"unknown argument {rest[0]}")
            for name, value in measure(instructions, trees):
                print(f"{name}\t{value}")
            return 0
        if argv[:1] == ["check"] and len(argv) == 3:
            budgets, measured = read_budgets(argv[1]), read_measured(argv[2])
            lines, failures = check(budgets, measured)
            print("\n".join(lines))
            for failure in failures:
                print(f"FAIL {failure}", file=sys.stderr)
            problems = self_check(measured)
            for problem in problems:
                print(f"error: the checker itself is wrong: {problem}", file=sys.stderr)
            return 1 if failures or problems else 0
        if argv[:1] == ["update"] and len(argv) == 3:
            changed, added = update(argv[1], read_measured(argv[2]))
            print(f"{argv[1]}: {len(changed)} budget(s) changed, {len(added)} added")
            for name in changed + added:
                print(f"  {name}")
            return 0
    except (OSError, subprocess.CalledProcessError, ValueError, BudgetError) as error:
        print(f"budgets.py: {error}", file=sys.stderr)
        return 2
    print("usage: budgets.py measure|check|update ... (see the top of this file)", file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
