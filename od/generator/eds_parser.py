"""EDS semantics: finds the object sections of an INI file, checks their structure and builds
the Device model. Every problem is reported to the Diagnostics with its line."""

import dataclasses
import re

from data_types import (OBJECT_ARRAY, OBJECT_CODE_NAMES, OBJECT_CODES, OBJECT_DOMAIN,
                        OBJECT_RECORD, OBJECT_VAR, UNSIGNED8)
from diagnostics import Diagnostics
from eds_model import Device, OdObject
from entry_parser import (check_group_range, key_line, optional_value, parse_entry,
                          parse_group_text, parse_number)
from ini_reader import IniEntry, IniFile, IniSection
from object_lists import check_object_lists

_OBJECT_SECTION = re.compile(r"^([0-9a-f]{1,4})$", re.IGNORECASE)
_SUB_SECTION = re.compile(r"^([0-9a-f]{1,4})sub([0-9a-f]+)$", re.IGNORECASE)
_EXTRA_SECTION = re.compile(r"^([0-9a-f]{1,4})(name|value|denotation)$", re.IGNORECASE)

MAX_SUB_INDEX = 0xFE
COMPACT_SUB0_NAME = "Highest sub-index supported"


class _Sections:
    """The object-related sections of a file, by index."""

    def __init__(self) -> None:
        self.objects = {}  # index -> IniSection
        self.subs = {}     # index -> {sub-index -> IniSection}
        self.names = {}    # index -> IniSection ([XXXXName])


def _classify(ini: IniFile, diag: Diagnostics) -> _Sections:
    found = _Sections()
    for section in ini.sections.values():
        match = _OBJECT_SECTION.match(section.name)
        if match:
            index = int(match.group(1), 16)
            if index == 0:
                diag.error(section.line, "index 0x0000 is not allowed")
            elif index in found.objects:
                diag.error(section.line, f"duplicate object 0x{index:04X} "
                                         f"(first at line {found.objects[index].line})")
            else:
                found.objects[index] = section
            continue
        match = _SUB_SECTION.match(section.name)
        if match:
            index, sub = int(match.group(1), 16), int(match.group(2), 16)
            subs = found.subs.setdefault(index, {})
            if sub == 0xFF:
                diag.error(section.line, "sub-index 0xFF is reserved")
            elif sub > 0xFF:
                diag.error(section.line, f"sub-index 0x{sub:X} is out of range (0..0xFE)")
            elif sub in subs:
                diag.error(section.line, f"duplicate sub-index 0x{index:04X}sub{sub:X} "
                                         f"(first at line {subs[sub].line})")
            else:
                subs[sub] = section
            continue
        match = _EXTRA_SECTION.match(section.name)
        if match:
            index, kind = int(match.group(1), 16), match.group(2).lower()
            if kind == "name":
                found.names[index] = section
            elif kind == "value":
                diag.error(section.line, f"[{section.name}]: value sections of compact "
                                         "objects are not supported")
    return found


def _compact_names(name_section, count: int, diag: Diagnostics) -> dict:
    """Sub-index -> name from an optional [XXXXName] section."""
    names = {}
    if name_section is None:
        return names
    for key, entry in name_section.entries.items():
        if key == "nrofentries":
            continue
        if key.isdigit() and 1 <= int(key) <= count:
            names[int(key)] = entry.value
        else:
            diag.warning(entry.line, f"[{name_section.name}]: ignoring key '{entry.key}'")
    return names


def _synthetic_section(template: IniSection, keys: dict) -> IniSection:
    section = IniSection(template.name, template.line)
    for key, value in keys.items():
        section.entries[key.lower()] = IniEntry(key, value, template.line)
    return section


def _compact_entries(index, section, count, name_section, group, diag):
    """The entries of an ARRAY with CompactSubObj=count."""
    if not 1 <= count <= MAX_SUB_INDEX:
        diag.error(key_line(section, "CompactSubObj"),
                   f"CompactSubObj={count} is outside 1..{MAX_SUB_INDEX}")
        return None
    sub_number = parse_number(section, "SubNumber", diag)
    if sub_number not in (None, 0, count + 1):
        diag.warning(key_line(section, "SubNumber"),
                     f"SubNumber={sub_number} ignored: CompactSubObj={count} means "
                     f"{count + 1} sub-indices")
    sub0_keys = {"DataType": "0x0005", "AccessType": "ro", "DefaultValue": str(count)}
    sub0 = parse_entry(index, 0, _synthetic_section(section, sub0_keys), diag,
                       name=COMPACT_SUB0_NAME, inherited_group=group)
    template = parse_entry(index, 1, section, diag, name="Sub1")
    if sub0 is None or template is None:
        return None
    names = _compact_names(name_section, count, diag)
    entries = [sub0]
    for sub in range(1, count + 1):
        entries.append(dataclasses.replace(template, sub=sub, name=names.get(sub, f"Sub{sub}")))
    return entries


def _explicit_entries(index, code, section, subs, group, diag):
    """The entries of an ARRAY or RECORD described by [XXXXsubN] sections."""
    sub_number = parse_number(section, "SubNumber", diag)
    if sub_number is None:
        if optional_value(section, "SubNumber") is None:
            diag.error(section.line, f"[{section.name}]: missing SubNumber")
    elif sub_number != len(subs):
        diag.error(key_line(section, "SubNumber"),
                   f"SubNumber={sub_number} but {len(subs)} sub-index sections are present")
    if 0 not in subs:
        diag.error(section.line, f"[{section.name}]: missing sub-index 0")
    entries = []
    for sub, sub_section in sorted(subs.items()):
        object_type = parse_number(sub_section, "ObjectType", diag)
        if object_type not in (None, OBJECT_VAR, OBJECT_DOMAIN):
            diag.error(key_line(sub_section, "ObjectType"),
                       f"a sub-index must have ObjectType 0x7 (VAR), not 0x{object_type:X}")
            continue
        entry = parse_entry(index, sub, sub_section, diag, inherited_group=group,
                            domain_object=object_type == OBJECT_DOMAIN)
        if entry is None:
            continue
        if sub == 0 and entry.data_type is not UNSIGNED8:
            diag.error(key_line(sub_section, "DataType"),
                       f"sub-index 0 of an {OBJECT_CODE_NAMES[code]} must be UNSIGNED8, "
                       f"not {entry.data_type.eds_name}")
            continue
        entries.append(entry)
    if len(entries) != len(subs) or 0 not in subs:
        return None
    if code == OBJECT_ARRAY and len({e.data_type.code for e in entries[1:]}) > 1:
        diag.warning(section.line, f"[{section.name}]: the elements of an ARRAY should all "
                                   "have the same DataType")
    return entries


def _parse_object(index, section, subs, name_section, diag):
    name_entry = optional_value(section, "ParameterName")
    if name_entry is None:
        diag.error(section.line, f"[{section.name}]: missing ParameterName")
        return None
    code = parse_number(section, "ObjectType", diag)
    if code is None:
        if optional_value(section, "ObjectType") is not None:
            return None
        code = OBJECT_VAR
    if code not in OBJECT_CODES:
        diag.error(key_line(section, "ObjectType"), f"unsupported ObjectType 0x{code:X} "
                                                    "(expected 0x2, 0x7, 0x8 or 0x9)")
        return None
    compact = parse_number(section, "CompactSubObj", diag) or 0
    if code in (OBJECT_VAR, OBJECT_DOMAIN):
        kind = OBJECT_CODE_NAMES[code]
        for sub_section in subs.values():
            diag.error(sub_section.line, f"{kind} object 0x{index:04X} cannot have "
                                         "sub-index sections")
        if compact:
            diag.error(key_line(section, "CompactSubObj"),
                       f"CompactSubObj is not allowed on a {kind}")
        entry = parse_entry(index, 0, section, diag, domain_object=code == OBJECT_DOMAIN)
        if entry is None or subs or compact:
            return None
        return OdObject(index, name_entry.value, code, [entry], section.line)
    group = None
    group_entry = optional_value(section, "CostaStorageGroup")
    if group_entry is not None:
        group = parse_group_text(group_entry, diag)
        if group is not None:
            check_group_range(index, group, group_entry.line, diag)
    if compact:
        if code == OBJECT_RECORD:
            diag.error(key_line(section, "CompactSubObj"),
                       "CompactSubObj is only allowed on an ARRAY")
            return None
        for sub_section in subs.values():
            diag.error(sub_section.line, f"[{sub_section.name}]: not allowed together with "
                                         "CompactSubObj")
        entries = _compact_entries(index, section, compact, name_section, group, diag)
        if subs:
            return None
    else:
        if name_section is not None:
            diag.warning(name_section.line, f"[{name_section.name}] ignored: object "
                                            f"0x{index:04X} has no CompactSubObj")
        entries = _explicit_entries(index, code, section, subs, group, diag)
    if entries is None:
        return None
    return OdObject(index, name_entry.value, code, entries, section.line)


DUMMY_TYPES = range(0x0002, 0x0008)  # INTEGER8..UNSIGNED32: whole bytes, as PDOs map


def _dummy_usage(ini: IniFile, diag: Diagnostics) -> int:
    """[DummyUsage] (CiA 306): bit n set when the dummy entry of data type 0x000n may be mapped
    into an RPDO. Without the section, none may. Dummy0001 (BOOLEAN, one bit) cannot be: PDOs
    map whole bytes."""
    section = ini.get("DummyUsage")
    if section is None:
        return 0
    usage = 0
    for data_type in range(0x0001, 0x0008):
        key = f"Dummy{data_type:04X}"
        value = parse_number(section, key, diag)
        if value is None or value == 0:
            continue
        line = key_line(section, key)
        if value != 1:
            diag.error(line, f"[{section.name}] {key}={value}: 0 or 1")
        elif data_type not in DUMMY_TYPES:
            diag.error(line, f"[{section.name}] {key}=1: a one-bit dummy entry cannot be "
                             "mapped (PDOs map whole bytes)")
        else:
            usage |= 1 << data_type
    return usage


def parse_eds(ini: IniFile, diag: Diagnostics, fallback_name: str) -> Device:
    """The device described by `ini`; check `diag.has_errors` before using it."""
    info = ini.get("DeviceInfo")
    product = info.value("ProductName") if info is not None else ""
    device = Device(product or fallback_name)
    device.dummy_usage = _dummy_usage(ini, diag)
    found = _classify(ini, diag)
    check_object_lists(ini, {i: s.line for i, s in found.objects.items()}, diag)
    for index, subs in sorted(found.subs.items()):
        if index not in found.objects:
            for sub_section in subs.values():
                diag.error(sub_section.line, f"[{sub_section.name}] has no object section "
                                             f"[{index:04X}]")
    for index, section in sorted(found.objects.items()):
        obj = _parse_object(index, section, found.subs.get(index, {}),
                            found.names.get(index), diag)
        if obj is not None:
            device.objects.append(obj)
    if not found.objects:
        diag.error(1, "the file defines no objects")
    return device
