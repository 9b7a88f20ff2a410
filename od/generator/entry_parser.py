"""Turns the keys of one sub-index (a VAR section, a `[XXXXsubN]` section or the object section
of a compact ARRAY) into a validated Entry."""

from data_types import (ACCESS_TYPES, DATA_TYPES, DOMAIN, FIRST_CUSTOM_GROUP,
                        GROUP_APPLICATION, GROUP_COMMUNICATION, GROUP_NAMES, GROUP_NONE,
                        HAS_LIMITS, IN_ROM, LAST_CUSTOM_GROUP, NODE_ID_RELATIVE,
                        PLAIN_INTEGER, WRITABLE_ACCESS, default_group)
from diagnostics import Diagnostics
from eds_model import Entry
from ini_reader import IniEntry, IniSection
from value_parser import parse_default, parse_integer, parse_limit, type_bounds

MAX_CAPACITY = 0xFFFF  # SubEntry::size is a uint16_t
LARGEST_NODE_ID = 127


def key_line(section: IniSection, key: str) -> int:
    """Line of `key` in `section`, or of the section header when the key is absent."""
    entry = section.get(key)
    return entry.line if entry is not None else section.line


def optional_value(section: IniSection, key: str):
    """The key's entry when present with a non-empty value (empty values count as absent)."""
    entry = section.get(key)
    return entry if entry is not None and entry.value else None


def parse_number(section: IniSection, key: str, diag: Diagnostics):
    """An integer key: its value, or None when absent or invalid (reported)."""
    entry = optional_value(section, key)
    if entry is None:
        return None
    try:
        return parse_integer(entry.value)
    except ValueError as exc:
        diag.error(entry.line, f"{key}: {exc}")
        return None


def parse_data_type(section: IniSection, diag: Diagnostics, domain_object: bool):
    code = parse_number(section, "DataType", diag)
    if code is None:
        if domain_object:
            return DOMAIN
        if optional_value(section, "DataType") is None:
            diag.error(section.line, f"[{section.name}]: missing DataType")
        return None
    data_type = DATA_TYPES.get(code)
    if data_type is None:
        diag.error(key_line(section, "DataType"), f"unknown data type 0x{code:04X}")
        return None
    if domain_object and data_type is not DOMAIN:
        diag.error(key_line(section, "DataType"),
                   f"a DOMAIN object must have DataType DOMAIN (0x000F), not "
                   f"{data_type.eds_name}")
        return None
    return data_type


def parse_access(section: IniSection, diag: Diagnostics):
    entry = optional_value(section, "AccessType")
    if entry is None:
        diag.error(section.line, f"[{section.name}]: missing AccessType")
        return None
    access = entry.value.lower()
    if access not in ACCESS_TYPES:
        diag.error(entry.line, f"unknown access type '{entry.value}' "
                               "(expected ro, wo, rw, rwr, rww or const)")
        return None
    return access


def parse_group_text(entry: IniEntry, diag: Diagnostics):
    text = entry.value.strip().lower()
    if text in GROUP_NAMES:
        return GROUP_NAMES[text]
    if text.isdigit() and FIRST_CUSTOM_GROUP <= int(text) <= LAST_CUSTOM_GROUP:
        return int(text)
    diag.error(entry.line, f"invalid CostaStorageGroup '{entry.value}' (expected none, "
                           f"communication, application, lss or "
                           f"{FIRST_CUSTOM_GROUP}..{LAST_CUSTOM_GROUP})")
    return None


def check_group_range(index: int, group: int, line: int, diag: Diagnostics):
    """A group reaches only the indices its reset loads: reset communication restores the
    defaults of 0x1000..0x1FFF and loads the communication group only."""
    if group == GROUP_COMMUNICATION and not 0x1000 <= index <= 0x1FFF:
        diag.error(line, "only an entry of 0x1000..0x1FFF can be in the communication group "
                         "(reset communication restores and loads exactly that range)")
    elif (group == GROUP_APPLICATION or group >= FIRST_CUSTOM_GROUP) and index < 0x2000:
        diag.error(line, "an entry below 0x2000 cannot be in the application or a custom "
                         "group (reset communication would restore its default without "
                         "loading its group)")


def _parse_group(index, section, access, data_type, inherited, diag):
    explicit = optional_value(section, "CostaStorageGroup")
    if explicit is not None:
        group = parse_group_text(explicit, diag)
        if group is None:
            return GROUP_NONE
        if group != GROUP_NONE and access == "const":
            diag.error(explicit.line, "a const entry cannot be stored: "
                                      "CostaStorageGroup must be none")
        elif group != GROUP_NONE and data_type is DOMAIN:
            diag.error(explicit.line, "a DOMAIN has no stored value: "
                                      "CostaStorageGroup must be none")
        else:
            check_group_range(index, group, explicit.line, diag)
        return group
    if access == "const" or data_type is DOMAIN:
        return GROUP_NONE
    if inherited is not None:
        return inherited
    return default_group(index, access)


def _parse_limits(section, data_type, diag):
    """(low, high) or None; None also after an error."""
    low_entry = optional_value(section, "LowLimit")
    high_entry = optional_value(section, "HighLimit")
    if low_entry is None and high_entry is None:
        return None
    if not data_type.is_numeric:
        for entry in (low_entry, high_entry):
            if entry is not None:
                diag.error(entry.line, f"{entry.key} is only allowed on numeric types, "
                                       f"not on {data_type.eds_name}")
        return None
    low, high = type_bounds(data_type)
    failed = False
    for entry, what in ((low_entry, "LowLimit"), (high_entry, "HighLimit")):
        if entry is None:
            continue
        try:
            value = parse_limit(entry.value, data_type, what)
        except ValueError as exc:
            diag.error(entry.line, str(exc))
            failed = True
            continue
        if what == "LowLimit":
            low = value
        else:
            high = value
    if failed:
        return None
    if low > high:
        diag.error(key_line(section, "LowLimit" if low_entry else "HighLimit"),
                   f"LowLimit {low!r} is greater than HighLimit {high!r}")
        return None
    return low, high


def _check_default_in_limits(section, default, relative, limits, diag):
    low, high = limits
    line = key_line(section, "DefaultValue")
    if not relative:
        if not low <= default <= high:
            diag.error(line, f"default outside limits: {default!r} is not in "
                             f"{low!r}..{high!r}")
        return
    if not (low <= default + 1 and default + LARGEST_NODE_ID <= high):
        diag.warning(line, f"$NODEID+{default} leaves the limits {low!r}..{high!r} "
                           f"for some node-ids")


def _parse_capacity(section, data_type, access, default, diag):
    if not data_type.is_string:
        entry = optional_value(section, "CostaStringLength")
        if entry is not None:
            diag.error(entry.line, "CostaStringLength is only allowed on VISIBLE_STRING "
                                   "and OCTET_STRING")
        return data_type.size
    length = len(default)
    line = key_line(section, "DefaultValue")
    if length > MAX_CAPACITY:
        diag.error(line, f"default is {length} bytes long; at most {MAX_CAPACITY} allowed")
        return 0
    capacity = parse_number(section, "CostaStringLength", diag)
    if capacity is not None:
        key = key_line(section, "CostaStringLength")
        if not 0 <= capacity <= MAX_CAPACITY:
            diag.error(key, f"CostaStringLength={capacity} is outside 0..{MAX_CAPACITY}")
            return 0
        if capacity < length:
            diag.error(key, f"CostaStringLength={capacity} is shorter than the default "
                            f"({length} bytes)")
        return capacity
    if data_type.kind == "visible" and length == 0 and access in WRITABLE_ACCESS:
        diag.error(section.line, f"[{section.name}]: writable string needs CostaStringLength")
    elif data_type.kind == "octet" and length == 0:
        diag.error(section.line, f"[{section.name}]: empty OCTET_STRING needs "
                                 "CostaStringLength or a DefaultValue")
    return length


def parse_entry(index: int, sub: int, section: IniSection, diag: Diagnostics, *,
                name: str = None, domain_object: bool = False, inherited_group=None):
    """The Entry described by `section`, or None after reporting errors.

    `name` replaces ParameterName (compact arrays); `inherited_group` is the storage group set
    on the enclosing ARRAY/RECORD section, if any."""
    errors_before = diag.error_count
    if name is None:
        name_entry = optional_value(section, "ParameterName")
        if name_entry is None:
            diag.error(section.line, f"[{section.name}]: missing ParameterName")
        name = name_entry.value if name_entry is not None else ""
    data_type = parse_data_type(section, diag, domain_object)
    access = parse_access(section, diag)
    mapping = parse_number(section, "PDOMapping", diag) or 0
    if mapping not in (0, 1):
        diag.error(key_line(section, "PDOMapping"), f"PDOMapping must be 0 or 1, not {mapping}")
    if data_type is None or access is None:
        return None
    default_entry = section.get("DefaultValue")
    try:
        parsed = parse_default(default_entry.value if default_entry else "", data_type)
    except ValueError as exc:
        diag.error(default_entry.line, str(exc))
        return None
    attributes, mapping_bits = ACCESS_TYPES[access]
    if mapping == 1:
        attributes |= mapping_bits
    if parsed.node_id_relative:
        attributes |= NODE_ID_RELATIVE
    limits = _parse_limits(section, data_type, diag)
    if limits is not None:
        attributes |= HAS_LIMITS
        _check_default_in_limits(section, parsed.value, parsed.node_id_relative, limits, diag)
    elif parsed.node_id_relative:
        low, high = type_bounds(data_type)
        if parsed.value + LARGEST_NODE_ID > high:
            diag.warning(key_line(section, "DefaultValue"),
                         f"$NODEID+{parsed.value} overflows {data_type.eds_name} "
                         "for some node-ids")
    if data_type.is_integer and not attributes & IN_ROM and limits is None:
        attributes |= PLAIN_INTEGER  # a write checks its length alone
    size = _parse_capacity(section, data_type, access, parsed.value, diag)
    group = _parse_group(index, section, access, data_type, inherited_group, diag)
    if diag.error_count != errors_before:
        return None
    return Entry(index=index, sub=sub, name=name, data_type=data_type, access=access,
                 attributes=attributes, default=parsed.value, size=size, group=group,
                 low=limits[0] if limits else None, high=limits[1] if limits else None,
                 line=section.line)
