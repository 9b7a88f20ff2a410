"""The validated content of an EDS: objects and their sub-entries."""

from dataclasses import dataclass, field

from data_types import (ATTRIBUTE_NAMES, DataType, HAS_LIMITS, IN_ROM, NODE_ID_RELATIVE,
                        OBJECT_ARRAY, OBJECT_RECORD)


@dataclass
class Entry:
    """One sub-index: everything the generated SubEntry row and the value blocks need."""
    index: int
    sub: int
    name: str
    data_type: DataType
    access: str                  # ro, wo, rw, rwr, rww, const
    attributes: int              # costa::od::Attribute bits
    default: object              # int, float or bytes; None for DOMAIN
    size: int                    # bytes; capacity for strings; 0 for DOMAIN
    group: int                   # storage group
    low: object = None           # limits when HAS_LIMITS is set
    high: object = None
    line: int = 0                # section line in the EDS

    @property
    def in_rom(self) -> bool:
        return bool(self.attributes & IN_ROM)

    @property
    def has_storage(self) -> bool:
        """DOMAINs have no value in either block."""
        return self.data_type.kind != "domain"

    @property
    def has_limits(self) -> bool:
        return bool(self.attributes & HAS_LIMITS)

    @property
    def node_id_relative(self) -> bool:
        return bool(self.attributes & NODE_ID_RELATIVE)

    def attribute_names(self) -> list:
        return [name for bit, name in ATTRIBUTE_NAMES if self.attributes & bit]


@dataclass
class OdObject:
    index: int
    name: str
    code: int                    # EDS ObjectType (0x2, 0x7, 0x8, 0x9)
    entries: list = field(default_factory=list)  # Entry, sorted by sub-index
    line: int = 0

    @property
    def is_compound(self) -> bool:
        return self.code in (OBJECT_ARRAY, OBJECT_RECORD)

    def entry(self, sub: int):
        for entry in self.entries:
            if entry.sub == sub:
                return entry
        return None

    def full_name(self, entry: Entry) -> str:
        """The name shown for `entry`: the object's for a VAR, 'object.sub' otherwise."""
        return f"{self.name}.{entry.name}" if self.is_compound else self.name


@dataclass
class Device:
    product_name: str
    objects: list = field(default_factory=list)  # OdObject, sorted by index
    dummy_usage: int = 0  # bit n: the dummy entry of data type 0x000n may be mapped

    def all_entries(self):
        for obj in self.objects:
            yield from obj.entries

    def find(self, index: int):
        for obj in self.objects:
            if obj.index == index:
                return obj
        return None
