"""Where every value lives: the members of the Values (RAM) and Constants (ROM) structs, and
the offsetof() expression of each sub-entry."""

from dataclasses import dataclass, field

from cpp_names import struct_member, struct_type, sub_members, var_member
from data_types import OBJECT_ARRAY, RPDO_MAPPABLE, TPDO_MAPPABLE
from eds_model import Device, Entry, OdObject

VALUES = "Values"
CONSTANTS = "Constants"


def element_suffix(entry: Entry) -> str:
    """Array bounds that follow the member name for one value of `entry`."""
    if entry.data_type.kind == "visible":
        return f"[{entry.size + 1}]"  # one more byte keeps the text NUL-terminated
    if entry.data_type.kind == "octet":
        return f"[{entry.size}]"
    return ""


def storage_bytes(entry: Entry) -> int:
    return entry.size + 1 if entry.data_type.kind == "visible" else entry.size


def element_type(entry: Entry) -> str:
    """The C++ type of one value, as written inside sizeof()."""
    return entry.data_type.cpp_type + element_suffix(entry)


@dataclass
class Member:
    """A member of a block or of a nested struct: one entry, or `item[N]` for N entries."""
    name: str
    entries: list

    @property
    def is_items(self) -> bool:
        return len(self.entries) > 1 or self.name == "item"

    def declaration(self) -> str:
        first = self.entries[0]
        count = f"[{len(self.entries)}]" if self.is_items else ""
        return f"{first.data_type.cpp_type} {self.name}{count}{element_suffix(first)};"


@dataclass
class BlockMember:
    """A member of Values or Constants: a VAR's value or the struct of an ARRAY/RECORD."""
    obj: OdObject
    name: str
    struct_type: str = ""             # empty for a VAR
    members: list = field(default_factory=list)  # Member; for a VAR exactly one


@dataclass
class Block:
    type_name: str                    # Values or Constants
    members: list = field(default_factory=list)  # BlockMember


@dataclass
class SizeCheck:
    expression: str                   # sizeof(...)
    size: int
    label: str


@dataclass
class Layout:
    values: Block
    constants: Block
    offsets: dict = field(default_factory=dict)      # (index, sub) -> C++ expression
    size_checks: list = field(default_factory=list)  # SizeCheck
    # Each stored entry's offset as a base and a part relative to it: the base of its object's
    # member of the block ((index, block type name) -> offsetof() expression), the offset within
    # that member ((index, sub) -> C++ expression, "0" for a VAR or a DOMAIN), and where in the
    # member that is, independent of names ((index, sub) -> (member position, item)).
    bases: dict = field(default_factory=dict)
    relative: dict = field(default_factory=dict)
    positions: dict = field(default_factory=dict)
    # The C++ types of an object's member of a block, in order ((index, block type name) ->
    # tuple): members of one shape have their values at the same relative offsets.
    shapes: dict = field(default_factory=dict)
    # (index, sub) of every entry in ROM, in the order of the objects and their members.
    rom_entries: list = field(default_factory=list)


def _items_form(obj: OdObject, block_entries: list) -> bool:
    """True when subs 1..N of an ARRAY all live in this block with one C++ type."""
    if obj.code != OBJECT_ARRAY:
        return False
    items = [e for e in obj.entries if e.sub != 0]
    if not items or [e.sub for e in items] != list(range(1, len(items) + 1)):
        return False
    first = items[0]
    return all(e in block_entries and e.data_type is first.data_type and e.size == first.size
               for e in items)


def _object_member(obj: OdObject, rom: bool):
    entries = [e for e in obj.entries if e.has_storage and e.in_rom == rom]
    if not entries:
        return None
    if not obj.is_compound:
        return BlockMember(obj, var_member(obj.index, obj.name),
                           members=[Member(var_member(obj.index, obj.name), entries)])
    member = BlockMember(obj, struct_member(obj.index, obj.name),
                         struct_type(obj.index, obj.name))
    names = sub_members([(e.sub, e.name) for e in obj.entries])
    if _items_form(obj, entries):
        member.members = [Member(names[e.sub], [e]) for e in entries if e.sub == 0]
        member.members.append(Member("item", [e for e in entries if e.sub != 0]))
    else:
        member.members = [Member(names[e.sub], [e]) for e in entries]
    return member


def _record_block(block: Block, layout: Layout) -> None:
    """Offsets and size checks of every entry stored in `block`."""
    owner = block.type_name
    for top in block.members:
        base = f"offsetof({owner}, {top.name})"
        layout.bases[(top.obj.index, owner)] = base
        layout.shapes[(top.obj.index, owner)] = (
            bool(top.struct_type),
            tuple((m.entries[0].data_type.cpp_type, element_suffix(m.entries[0]),
                   len(m.entries) if m.is_items else 0) for m in top.members))
        for position, member in enumerate(top.members):
            if top.struct_type:
                scope = f"{owner}::{top.struct_type}"
                inner = f"offsetof({scope}, {member.name})"
                where = f"{base} + {inner}"
                qualified = f"{scope}::{member.name}"
            else:
                inner = "0"
                where, qualified = base, f"{owner}::{member.name}"
            first = member.entries[0]
            for k, entry in enumerate(member.entries):
                step = f" + {k} * sizeof({element_type(entry)})" if k else ""
                key = (entry.index, entry.sub)
                layout.relative[key] = inner + step
                layout.positions[key] = (position, k)
            if not member.is_items:
                layout.offsets[(first.index, first.sub)] = where
                layout.size_checks.append(SizeCheck(f"sizeof({qualified})",
                                                    storage_bytes(first),
                                                    f"0x{first.index:04X}:{first.sub}"))
                continue
            for k, entry in enumerate(member.entries):
                step = f" + {k} * sizeof({element_type(entry)})" if k else ""
                layout.offsets[(entry.index, entry.sub)] = where + step
            layout.size_checks.append(SizeCheck(f"sizeof({qualified}[0])",
                                                storage_bytes(first),
                                                f"0x{first.index:04X}:1"))
            layout.size_checks.append(SizeCheck(f"sizeof({qualified})",
                                                storage_bytes(first) * len(member.entries),
                                                f"0x{first.index:04X}:1..{len(member.entries)}"))


def _constants_key(member: BlockMember) -> tuple:
    """What a member of Constants holds: its C++ types and every value's default."""
    return (member.struct_type != "",
            tuple((m.entries[0].data_type.cpp_type, element_suffix(m.entries[0]), m.is_items,
                   tuple((e.data_type.code, e.size, repr(e.default), e.node_id_relative)
                         for e in m.entries))
                  for m in member.members))


def _mappable(member: BlockMember) -> bool:
    """True when a PDO may map one of its values: a PDO tells its entries apart by where their
    values are, so such a constant keeps a place of its own."""
    return any(e.attributes & (RPDO_MAPPABLE | TPDO_MAPPABLE)
               for m in member.members for e in m.entries)


def _share_constants(layout: Layout, shared: dict) -> None:
    """The entries of objects whose constants equal an earlier object's (`shared`: index ->
    that object's index) at that object's offsets: one copy of the values in ROM."""
    for index, owner in shared.items():
        layout.bases[(index, CONSTANTS)] = layout.bases[(owner, CONSTANTS)]
        layout.shapes[(index, CONSTANTS)] = layout.shapes[(owner, CONSTANTS)]
        own = [k for k in layout.rom_entries if k[0] == index]
        theirs = [k for k in layout.rom_entries if k[0] == owner]
        for key, their in zip(own, theirs):
            layout.offsets[key] = layout.offsets[their]
            layout.relative[key] = layout.relative[their]
            layout.positions[key] = layout.positions[their]


def plan_layout(device: Device) -> Layout:
    values, constants = Block(VALUES), Block(CONSTANTS)
    owners, shared, rom_entries = {}, {}, []
    for obj in device.objects:
        member = _object_member(obj, False)
        if member is not None:
            values.members.append(member)
        member = _object_member(obj, True)
        if member is None:
            continue
        rom_entries += [(e.index, e.sub) for m in member.members for e in m.entries]
        key = _constants_key(member)
        if _mappable(member):
            constants.members.append(member)  # never shared, neither way
            continue
        if key in owners:
            shared[obj.index] = owners[key]  # the same constants as an earlier object: shared
        else:
            owners[key] = obj.index
            constants.members.append(member)
    layout = Layout(values, constants)
    layout.rom_entries = rom_entries
    _record_block(values, layout)
    _record_block(constants, layout)
    _share_constants(layout, shared)
    for entry in device.all_entries():  # DOMAINs
        layout.offsets.setdefault((entry.index, entry.sub), "0")
        layout.relative.setdefault((entry.index, entry.sub), "0")
        layout.positions.setdefault((entry.index, entry.sub), (0, 0))
    return layout
