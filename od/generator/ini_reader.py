"""A line-tracking reader for the INI dialect of CiA 306 device descriptions.

- `[Section]` headers and `Key=Value` lines; section names and keys are case-insensitive.
- Lines whose first non-blank character is `;` are comments; blank lines are skipped.
- Keys and values are trimmed; a value keeps any `;` it contains.
- A repeated section or a repeated key within a section is an error; the first one wins.
"""

from dataclasses import dataclass, field

from diagnostics import Diagnostics


@dataclass
class IniEntry:
    key: str    # as written
    value: str  # trimmed
    line: int


@dataclass
class IniSection:
    name: str  # as written, without brackets
    line: int
    entries: dict = field(default_factory=dict)  # lower-case key -> IniEntry

    def get(self, key: str):
        """The entry for `key` (any case), or None."""
        return self.entries.get(key.lower())

    def value(self, key: str, default: str = "") -> str:
        entry = self.get(key)
        return entry.value if entry is not None else default


@dataclass
class IniFile:
    sections: dict = field(default_factory=dict)  # lower-case name -> IniSection

    def get(self, name: str):
        return self.sections.get(name.lower())


def decode_text(data: bytes) -> str:
    """UTF-8 (with or without BOM); files that are not valid UTF-8 are read as Latin-1."""
    if data.startswith(b"\xef\xbb\xbf"):
        data = data[3:]
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return data.decode("latin-1")


def read_ini(text: str, diag: Diagnostics) -> IniFile:
    ini = IniFile()
    current = None  # section receiving keys; None before the first header or in a duplicate
    in_duplicate = False
    for number, raw in enumerate(text.split("\n"), start=1):
        line = raw.strip()
        if not line or line.startswith(";"):
            continue
        if line.startswith("["):
            if not line.endswith("]") or len(line) < 3:
                diag.error(number, f"malformed section header '{line}'")
                current, in_duplicate = None, True
                continue
            name = line[1:-1].strip()
            if not name:
                diag.error(number, "empty section name")
                current, in_duplicate = None, True
                continue
            first = ini.sections.get(name.lower())
            if first is not None:
                diag.error(number, f"duplicate section [{name}] (first at line {first.line})")
                current, in_duplicate = None, True
                continue
            current = IniSection(name, number)
            ini.sections[name.lower()] = current
            in_duplicate = False
            continue
        key, sep, value = line.partition("=")
        key, value = key.strip(), value.strip()
        if not sep:
            diag.error(number, f"expected 'Key=Value' or '[Section]', found '{line}'")
            continue
        if not key:
            diag.error(number, "missing key before '='")
            continue
        if current is None:
            if not in_duplicate:
                diag.error(number, f"key '{key}' outside of any section")
            continue
        first = current.entries.get(key.lower())
        if first is not None:
            diag.error(number, f"duplicate key '{key}' in [{current.name}] "
                               f"(first at line {first.line})")
            continue
        current.entries[key.lower()] = IniEntry(key, value, number)
    return ini
