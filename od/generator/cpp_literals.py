"""C++ spellings of values: numbers, strings, limit patterns, comments."""

import re
import struct

from data_types import DataType, integer_range
from value_parser import to_float32

_UINT64_MASK = (1 << 64) - 1
_COMMENT_SAFE = re.compile(r"[^A-Za-z0-9 .,:;()+\-_'#&%=<>!@$^*|~\[\]{}]")


def c_string(data: bytes) -> str:
    """A C string literal holding exactly `data`. Non-printable and non-ASCII bytes become
    three-digit octal escapes (which never swallow a following digit); '?' is escaped so no
    trigraph can form."""
    out = ['"']
    for byte in data:
        char = chr(byte)
        if char in '"\\?':
            out.append("\\" + char)
        elif 0x20 <= byte < 0x7F:
            out.append(char)
        else:
            out.append(f"\\{byte:03o}")
    out.append('"')
    return "".join(out)


def text_literal(text: str) -> str:
    return c_string(text.encode("utf-8"))


def comment_text(text: str) -> str:
    """`text` reduced to characters that are harmless inside a // comment."""
    return _COMMENT_SAFE.sub("_", text)


def float32_literal(value: float) -> str:
    """The shortest decimal that reads back as the same binary32 number, with suffix F."""
    for precision in range(1, 10):
        text = f"{value:.{precision}g}"
        if to_float32(float(text)) == value:
            break
    return float64_literal(float(text)) + "F"  # Python's spelling of the same short decimal


def float64_literal(value: float) -> str:
    text = repr(value)  # shortest round-trip spelling
    if "." not in text and "e" not in text:
        text += ".0"
    return text


def integer_literal(value: int, data_type: DataType) -> str:
    kind, size = data_type.kind, data_type.size
    if kind in ("bool", "unsigned"):
        if size == 8:
            return f"0x{value:016X}ULL"
        return f"0x{value:08X}U" if size == 4 else f"{value}U"
    low = integer_range(data_type)[0]
    if size == 8:
        return "(-9223372036854775807LL - 1)" if value == low else f"{value}LL"
    if size == 4 and value == low:
        return "(-2147483647 - 1)"
    return str(value)


def scalar_literal(value, data_type: DataType) -> str:
    """Initializer of a numeric value."""
    if data_type.kind == "real":
        return float32_literal(value) if data_type.size == 4 else float64_literal(value)
    return integer_literal(value, data_type)


def octets_literal(data: bytes, capacity: int) -> str:
    """Initializer of a uint8_t[capacity] array: every byte written, zeros after the data."""
    padded = data + bytes(capacity - len(data))
    return "{" + ", ".join(f"0x{b:02X}U" for b in padded) + "}"


def limit_pattern(value, data_type: DataType) -> int:
    """The raw 64-bit pattern of a limit: unsigned values as they are, signed values in two's
    complement, reals as the bits of a double."""
    if data_type.kind == "real":
        return struct.unpack("<Q", struct.pack("<d", value))[0]
    return value & _UINT64_MASK


def pattern_literal(pattern: int) -> str:
    return f"0x{pattern:016X}ULL"

