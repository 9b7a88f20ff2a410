"""CiA 301 data types, access types, attributes and storage groups as the generator sees them.

The numeric values here mirror od/include/costa/od/definition.hpp and data_type.hpp; the
emitted C++ refers to those headers by symbol, so the two cannot drift apart silently.
"""

from dataclasses import dataclass


@dataclass(frozen=True)
class DataType:
    code: int         # EDS DataType value
    eds_name: str     # name used in messages (BOOLEAN, UNSIGNED8, ...)
    enumerator: str   # costa::od::DataType enumerator
    kind: str         # 'bool', 'signed', 'unsigned', 'real', 'visible', 'octet', 'domain'
    size: int         # bytes of a fixed-size value; 0 for strings and DOMAIN
    cpp_type: str     # C++ element type of the stored value ('' for DOMAIN)

    @property
    def is_integer(self) -> bool:
        return self.kind in ("signed", "unsigned")

    @property
    def is_numeric(self) -> bool:
        return self.kind in ("bool", "signed", "unsigned", "real")

    @property
    def is_string(self) -> bool:
        return self.kind in ("visible", "octet")


_TYPES = (
    DataType(0x0001, "BOOLEAN", "kBoolean", "bool", 1, "uint8_t"),
    DataType(0x0002, "INTEGER8", "kInteger8", "signed", 1, "int8_t"),
    DataType(0x0003, "INTEGER16", "kInteger16", "signed", 2, "int16_t"),
    DataType(0x0004, "INTEGER32", "kInteger32", "signed", 4, "int32_t"),
    DataType(0x0005, "UNSIGNED8", "kUnsigned8", "unsigned", 1, "uint8_t"),
    DataType(0x0006, "UNSIGNED16", "kUnsigned16", "unsigned", 2, "uint16_t"),
    DataType(0x0007, "UNSIGNED32", "kUnsigned32", "unsigned", 4, "uint32_t"),
    DataType(0x0008, "REAL32", "kReal32", "real", 4, "float"),
    DataType(0x0009, "VISIBLE_STRING", "kVisibleString", "visible", 0, "char"),
    DataType(0x000A, "OCTET_STRING", "kOctetString", "octet", 0, "uint8_t"),
    DataType(0x000F, "DOMAIN", "kDomain", "domain", 0, ""),
    DataType(0x0011, "REAL64", "kReal64", "real", 8, "double"),
    DataType(0x0015, "INTEGER64", "kInteger64", "signed", 8, "int64_t"),
    DataType(0x001B, "UNSIGNED64", "kUnsigned64", "unsigned", 8, "uint64_t"),
)

DATA_TYPES = {t.code: t for t in _TYPES}
UNSIGNED8 = DATA_TYPES[0x0005]
DOMAIN = DATA_TYPES[0x000F]


def integer_range(data_type: DataType) -> tuple:
    """Smallest and largest value of an integer or boolean type."""
    bits = 8 * data_type.size
    if data_type.kind == "bool":
        return 0, 1
    if data_type.kind == "signed":
        return -(1 << (bits - 1)), (1 << (bits - 1)) - 1
    return 0, (1 << bits) - 1


# Object codes (EDS ObjectType) and their costa::od::ObjectCode enumerators.
OBJECT_DOMAIN = 0x2
OBJECT_VAR = 0x7
OBJECT_ARRAY = 0x8
OBJECT_RECORD = 0x9
OBJECT_CODES = {
    OBJECT_DOMAIN: "kDomain",
    OBJECT_VAR: "kVar",
    OBJECT_ARRAY: "kArray",
    OBJECT_RECORD: "kRecord",
}
OBJECT_CODE_NAMES = {
    OBJECT_DOMAIN: "DOMAIN",
    OBJECT_VAR: "VAR",
    OBJECT_ARRAY: "ARRAY",
    OBJECT_RECORD: "RECORD",
}

# Attribute bits (costa::od::Attribute), in the order they are written out.
READABLE = 1 << 0
WRITABLE = 1 << 1
IN_ROM = 1 << 2
RPDO_MAPPABLE = 1 << 3
TPDO_MAPPABLE = 1 << 4
NODE_ID_RELATIVE = 1 << 5
HAS_LIMITS = 1 << 6
PLAIN_INTEGER = 1 << 7
ATTRIBUTE_NAMES = (
    (READABLE, "kReadable"),
    (WRITABLE, "kWritable"),
    (IN_ROM, "kInRom"),
    (RPDO_MAPPABLE, "kRpdoMappable"),
    (TPDO_MAPPABLE, "kTpdoMappable"),
    (NODE_ID_RELATIVE, "kNodeIdRelative"),
    (HAS_LIMITS, "kHasLimits"),
    (PLAIN_INTEGER, "kPlainInteger"),
)

# AccessType -> (access attribute bits, attribute bits added by PDOMapping=1).
ACCESS_TYPES = {
    "ro": (READABLE, TPDO_MAPPABLE),
    "wo": (WRITABLE, RPDO_MAPPABLE),
    "rw": (READABLE | WRITABLE, RPDO_MAPPABLE | TPDO_MAPPABLE),
    "rwr": (READABLE | WRITABLE, TPDO_MAPPABLE),
    "rww": (READABLE | WRITABLE, RPDO_MAPPABLE),
    "const": (READABLE | IN_ROM, TPDO_MAPPABLE),
}
WRITABLE_ACCESS = ("wo", "rw", "rwr", "rww")

# Storage groups (costa::od::StorageGroup).
GROUP_NONE = 0
GROUP_COMMUNICATION = 1
GROUP_APPLICATION = 2
GROUP_LSS = 3
GROUP_NAMES = {
    "none": GROUP_NONE,
    "communication": GROUP_COMMUNICATION,
    "application": GROUP_APPLICATION,
    "lss": GROUP_LSS,
}
GROUP_ENUMERATORS = {
    GROUP_NONE: "kGroupNone",
    GROUP_COMMUNICATION: "kGroupCommunication",
    GROUP_APPLICATION: "kGroupApplication",
    GROUP_LSS: "kGroupLss",
}
FIRST_CUSTOM_GROUP = 4
LAST_CUSTOM_GROUP = 31  # 0x1010/0x1011 reach groups through a 32-bit mask

# Communication objects that are never stored by default.
UNSTORED_COMMUNICATION = (0x1003, 0x1010, 0x1011)


def default_group(index: int, access: str) -> int:
    """Storage group of an entry that has no CostaStorageGroup key."""
    if access not in WRITABLE_ACCESS:
        return GROUP_NONE
    if 0x1000 <= index <= 0x1FFF:
        return GROUP_NONE if index in UNSTORED_COMMUNICATION else GROUP_COMMUNICATION
    if index >= 0x2000:
        return GROUP_APPLICATION
    return GROUP_NONE
