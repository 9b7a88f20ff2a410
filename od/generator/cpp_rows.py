"""The rows of kRows (od::SubEntry): runs of like sub-indices stored back to back, and where
each object's run lies in kRows, objects of one shape sharing theirs."""

from dataclasses import dataclass, field

from cpp_layout import CONSTANTS, VALUES, Layout
from cpp_literals import comment_text
from eds_model import Device, Entry

MERGEABLE_KINDS = ("bool", "signed", "unsigned", "real")  # fixed-size values


def attributes_text(entry: Entry) -> str:
    return " | ".join(f"costa::od::{n}" for n in entry.attribute_names())


def rows_of(obj, row_of: dict) -> list:
    """The rows of an object: runs of consecutive sub-indices that share every property of a
    SubEntry and store fixed-size values back to back (array items, record members of one
    type). Each row is a list of entries."""
    rows = []
    for entry in obj.entries:
        if rows:
            last = rows[-1][-1]
            same = (entry.sub == last.sub + 1 and len(rows[-1]) < 255
                    and entry.data_type is last.data_type
                    and entry.data_type.kind in MERGEABLE_KINDS
                    and entry.attributes == last.attributes and entry.size == last.size
                    and entry.group == last.group
                    and row_of.get((entry.index, entry.sub)) == row_of.get((last.index, last.sub)))
            if same:
                rows[-1].append(entry)
                continue
        rows.append([entry])
    return rows


@dataclass
class _RowRun:
    label: str   # the objects that use it, for the comment above it
    rows: list   # rows_of() of the first of them


@dataclass
class _PlacedRows:
    runs: list = field(default_factory=list)        # _RowRun, in the order of kRows
    # index -> its _RowRun while runs are placed, then the position of its first row in kRows
    first_rows: dict = field(default_factory=dict)
    row_counts: dict = field(default_factory=dict)  # index -> rows of the object
    shared_checks: list = field(default_factory=list)  # (offset, offset it shares, label)


def _row_key(row: list, layout: Layout, row_of: dict) -> tuple:
    """What a row of kRows holds, independent of its object: equal keys, equal rows."""
    first = row[0]
    key = (first.index, first.sub)
    block = CONSTANTS if first.in_rom else VALUES
    return (first.sub, len(row), first.data_type.enumerator, attributes_text(first),
            first.size, first.group, row_of.get(key), block, layout.positions[key])


def place_rows(device: Device, layout: Layout, row_of: dict) -> _PlacedRows:
    """The runs of kRows: one per shape of object (its rows, and the C++ types of its members
    of each block, which put its values at the same offsets from its bases), less those of one
    row that begins a longer run (_share_first_rows())."""
    placed, seen = _PlacedRows(), {}
    for obj in device.objects:
        rows = rows_of(obj, row_of)
        # ROM rows hold where their values are in the constants block: objects share them only
        # when they share their constants.
        shape = (layout.shapes.get((obj.index, VALUES)), layout.shapes.get((obj.index, CONSTANTS)),
                 layout.bases.get((obj.index, CONSTANTS)),
                 tuple(_row_key(row, layout, row_of) for row in rows))
        placed.row_counts[obj.index] = len(rows)
        label = f"0x{obj.index:04X} {comment_text(obj.name)}"
        if shape in seen:
            run = seen[shape]
            placed.first_rows[obj.index] = run
            run.label += f", 0x{obj.index:04X}"
            for own, shared in zip(rows, run.rows):
                own_key, shared_key = (own[0].index, own[0].sub), (shared[0].index, shared[0].sub)
                if layout.relative[own_key] != layout.relative[shared_key]:
                    placed.shared_checks.append((layout.relative[own_key],
                                                 layout.relative[shared_key],
                                                 f"0x{own[0].index:04X}:{own[0].sub}"))
            continue
        run = _RowRun(label, rows)
        seen[shape] = run
        placed.first_rows[obj.index] = run
        placed.runs.append(run)
    _share_first_rows(placed, layout, row_of)
    return placed


def _share_first_rows(placed: _PlacedRows, layout: Layout, row_of: dict) -> None:
    """Drops the runs of one RAM row that equals the first row of a longer run (a VAR like the
    sub-index 0 of a record, both at offset 0 of their member of Values): their objects take
    that row. Then turns placed.first_rows from runs into positions in kRows."""
    longer = {}
    for run in placed.runs:
        if len(run.rows) > 1:
            longer.setdefault(_row_key(run.rows[0], layout, row_of), run)
    into, kept = {}, []
    for run in placed.runs:
        first = run.rows[0][0]
        target = (longer.get(_row_key(run.rows[0], layout, row_of))
                  if len(run.rows) == 1 and not first.in_rom else None)
        if target is None:
            kept.append(run)
            continue
        into[id(run)] = target
        shared = target.rows[0][0]
        users = [index for index, owner in placed.first_rows.items() if owner is run]
        target.label += "".join(f", 0x{index:04X}" for index in users)
        for index in users:
            if layout.relative[(index, first.sub)] != layout.relative[(shared.index, shared.sub)]:
                placed.shared_checks.append((layout.relative[(index, first.sub)],
                                             layout.relative[(shared.index, shared.sub)],
                                             f"0x{index:04X}:{first.sub}"))
    positions, row = {}, 0
    for run in kept:
        positions[id(run)] = row
        row += len(run.rows)
    placed.runs = kept
    for index, run in placed.first_rows.items():
        placed.first_rows[index] = positions[id(into.get(id(run), run))]
