"""Checks [MandatoryObjects], [OptionalObjects] and [ManufacturerObjects] against the object
sections of the file, in both directions."""

from diagnostics import Diagnostics
from ini_reader import IniFile
from value_parser import parse_integer

LIST_SECTIONS = ("MandatoryObjects", "OptionalObjects", "ManufacturerObjects")


def _in_manufacturer_range(index: int) -> bool:
    return 0x2000 <= index <= 0x5FFF


def _read_list(section, listed: dict, diag: Diagnostics) -> None:
    """Adds the indices of one list section to `listed` (index -> line)."""
    count_entry = section.get("SupportedObjects")
    count = None
    if count_entry is None or not count_entry.value:
        diag.error(section.line, f"[{section.name}]: missing SupportedObjects")
    else:
        try:
            count = parse_integer(count_entry.value)
        except ValueError as exc:
            diag.error(count_entry.line, f"SupportedObjects: {exc}")
    numbered = 0
    for key, entry in section.entries.items():
        if key == "supportedobjects":
            continue
        if not key.isdigit():
            diag.warning(entry.line, f"[{section.name}]: ignoring key '{entry.key}'")
            continue
        numbered += 1
        if count is not None and not 1 <= int(key) <= count:
            diag.error(entry.line, f"[{section.name}]: entry {entry.key} is outside "
                                   f"1..SupportedObjects ({count})")
        try:
            index = parse_integer(entry.value)
        except ValueError as exc:
            diag.error(entry.line, f"[{section.name}]: {exc}")
            continue
        if not 0 < index <= 0xFFFF:
            diag.error(entry.line, f"[{section.name}]: invalid object index {entry.value}")
            continue
        if index in listed:
            diag.error(entry.line, f"object 0x{index:04X} is listed twice "
                                   f"(first at line {listed[index]})")
            continue
        listed[index] = entry.line
        manufacturer = section.name.lower() == "manufacturerobjects"
        if manufacturer != _in_manufacturer_range(index):
            where = "inside" if _in_manufacturer_range(index) else "outside"
            diag.warning(entry.line, f"object 0x{index:04X} is {where} 0x2000..0x5FFF but "
                                     f"listed in [{section.name}]")
    if count is not None and count != numbered:
        diag.error(count_entry.line, f"[{section.name}]: SupportedObjects={count} but "
                                     f"{numbered} objects are listed")


def check_object_lists(ini: IniFile, object_lines: dict, diag: Diagnostics) -> None:
    """`object_lines` maps the index of every object section to its header line. Nothing is
    checked when the file has none of the list sections."""
    sections = [ini.get(name) for name in LIST_SECTIONS]
    if all(section is None for section in sections):
        return
    listed = {}
    for section in sections:
        if section is not None:
            _read_list(section, listed, diag)
    for index, line in sorted(listed.items()):
        if index not in object_lines:
            diag.error(line, f"object 0x{index:04X} is listed but has no section [{index:04X}]")
    for index, line in sorted(object_lines.items()):
        if index not in listed:
            diag.error(line, f"object 0x{index:04X} is not listed in [MandatoryObjects], "
                             "[OptionalObjects] or [ManufacturerObjects]")
