"""Parsing of DefaultValue, LowLimit and HighLimit texts into Python values.

Every function raises ValueError with a message meant for the user when the text is invalid.
Integers and booleans parse to int, reals to float (REAL32 values rounded to binary32),
strings to bytes; DOMAIN values are ignored.
"""

import math
import re
import struct
from dataclasses import dataclass

from data_types import DataType, integer_range

# CiA 306: decimal, hexadecimal with 0x, octal with a leading 0; an optional sign.
_INTEGER = re.compile(r"^[+-]?(0[xX][0-9a-fA-F]+|0[0-7]*|[1-9][0-9]*)$")
_REAL = re.compile(r"^[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?$")
_NODE_ID = re.compile(r"\$nodeid", re.IGNORECASE)
_NODE_ID_PLUS = re.compile(r"^\$nodeid\s*(?:\+\s*(.+))?$", re.IGNORECASE)
_PLUS_NODE_ID = re.compile(r"^(.+?)\s*\+\s*\$nodeid$", re.IGNORECASE)


@dataclass(frozen=True)
class ParsedValue:
    value: object               # int, float or bytes; None for DOMAIN
    node_id_relative: bool = False


def parse_integer(text: str) -> int:
    """An integer in any CiA 306 notation."""
    text = text.strip()
    if not _INTEGER.match(text):
        if re.match(r"^[+-]?0[0-9]+$", text):
            raise ValueError(f"invalid integer '{text}' (a leading 0 means octal)")
        raise ValueError(f"invalid integer '{text}'")
    sign = -1 if text.startswith("-") else 1
    digits = text.lstrip("+-")
    if digits[:2].lower() == "0x":
        magnitude = int(digits[2:], 16)
    elif len(digits) > 1 and digits.startswith("0"):
        magnitude = int(digits[1:], 8)
    else:
        magnitude = int(digits, 10)
    return sign * magnitude


def to_float32(value: float) -> float:
    """`value` rounded to the nearest binary32 number; ValueError when it does not fit."""
    try:
        return struct.unpack("<f", struct.pack("<f", value))[0]
    except OverflowError:
        raise ValueError(f"{value!r} is out of range for REAL32") from None


def _check_range(value: int, data_type: DataType, what: str) -> int:
    low, high = integer_range(data_type)
    if not low <= value <= high:
        raise ValueError(f"{what} {value} is out of range for {data_type.eds_name} "
                         f"({low}..{high})")
    return value


def _parse_real(text: str, data_type: DataType, what: str) -> float:
    if not _REAL.match(text):
        raise ValueError(f"invalid {data_type.eds_name} {what} '{text}'")
    value = float(text)
    if not math.isfinite(value):
        raise ValueError(f"{what} '{text}' is not a finite {data_type.eds_name}")
    if data_type.size == 4:
        value = to_float32(value)
        if not math.isfinite(value):
            raise ValueError(f"{what} '{text}' is not a finite REAL32")
    return value


def _parse_boolean(text: str, what: str) -> int:
    lowered = text.lower()
    if lowered == "true":
        return 1
    if lowered == "false":
        return 0
    value = parse_integer(text)
    if value not in (0, 1):
        raise ValueError(f"{what} {value} is out of range for BOOLEAN (0..1, TRUE, FALSE)")
    return value


def _parse_octets(text: str) -> bytes:
    digits = "".join(text.split())
    if not re.match(r"^[0-9a-fA-F]*$", digits) or len(digits) % 2:
        raise ValueError(f"invalid OCTET_STRING '{text}' (expected hex bytes such as '01 A0')")
    return bytes.fromhex(digits)


def _parse_node_id(text: str, data_type: DataType) -> int:
    """The number added to $NODEID in `text`."""
    match = _NODE_ID_PLUS.match(text)
    if match:
        operand = match.group(1)
    else:
        match = _PLUS_NODE_ID.match(text)
        if not match:
            raise ValueError(f"invalid $NODEID expression '{text}' "
                             "(use $NODEID, $NODEID+<integer> or <integer>+$NODEID)")
        operand = match.group(1)
    base = 0 if operand is None else parse_integer(operand)
    return _check_range(base, data_type, "default")


def parse_default(text: str, data_type: DataType) -> ParsedValue:
    """The DefaultValue of an entry; empty text means zero or an empty string."""
    text = text.strip()
    if data_type.kind == "domain":
        return ParsedValue(None)
    if _NODE_ID.search(text):
        if not data_type.is_integer:
            raise ValueError(f"$NODEID is not allowed in a {data_type.eds_name} default")
        return ParsedValue(_parse_node_id(text, data_type), True)
    if data_type.kind == "visible":
        return ParsedValue(text.encode("utf-8"))
    if data_type.kind == "octet":
        return ParsedValue(_parse_octets(text))
    if not text:
        return ParsedValue(0.0 if data_type.kind == "real" else 0)
    if data_type.kind == "real":
        return ParsedValue(_parse_real(text, data_type, "default"))
    if data_type.kind == "bool":
        return ParsedValue(_parse_boolean(text, "default"))
    return ParsedValue(_check_range(parse_integer(text), data_type, "default"))


def parse_limit(text: str, data_type: DataType, what: str):
    """LowLimit or HighLimit (`what`) of a numeric entry."""
    text = text.strip()
    if _NODE_ID.search(text):
        raise ValueError(f"$NODEID is not allowed in {what}")
    if data_type.kind == "real":
        return _parse_real(text, data_type, what)
    if data_type.kind == "bool":
        return _parse_boolean(text, what)
    return _check_range(parse_integer(text), data_type, what)


def type_bounds(data_type: DataType) -> tuple:
    """The limits an entry has when only one of LowLimit and HighLimit is given."""
    if data_type.kind == "real":
        largest = struct.unpack("<f", b"\xff\xff\x7f\x7f")[0] if data_type.size == 4 \
            else 1.7976931348623157e308
        return -largest, largest
    return integer_range(data_type)
