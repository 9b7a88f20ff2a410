"""C++ identifiers derived from EDS ParameterNames."""

import re

CPP_KEYWORDS = frozenset("""
alignas alignof and and_eq asm auto bitand bitor bool break case catch char char8_t char16_t
char32_t class compl concept const consteval constexpr constinit const_cast continue co_await
co_return co_yield decltype default delete do double dynamic_cast else enum explicit export
extern false float for friend goto if inline int long mutable namespace new noexcept not
not_eq nullptr operator or or_eq private protected public register reinterpret_cast requires
return short signed sizeof static static_assert static_cast struct switch template this
thread_local throw true try typedef typeid typename union unsigned using virtual void volatile
wchar_t while xor xor_eq
""".split())

# Names a sub-entry member never gets: `item` is the array of an ARRAY's elements.
RESERVED_MEMBERS = CPP_KEYWORDS | {"item"}

_IDENTIFIER = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")


def is_identifier(name: str) -> bool:
    return bool(_IDENTIFIER.match(name)) and name not in CPP_KEYWORDS


def sanitize(name: str) -> str:
    """Lower case; every run of characters other than ASCII letters and digits becomes one
    '_'; no '_' at either end."""
    return re.sub(r"[^a-z0-9]+", "_", name.lower()).strip("_")


def camel_case(sanitized: str) -> str:
    return "".join(part[:1].upper() + part[1:] for part in sanitized.split("_") if part)


def var_member(index: int, name: str) -> str:
    """Member of Values/Constants holding a VAR: x1017_producer_heartbeat_time."""
    base = sanitize(name)
    return f"x{index:04x}_{base}" if base else f"x{index:04x}"


def struct_member(index: int, name: str) -> str:
    """Member holding the struct of an ARRAY/RECORD; same scheme as a VAR."""
    return var_member(index, name)


def struct_type(index: int, name: str) -> str:
    """Nested struct type of an ARRAY/RECORD: X1018IdentityObject."""
    return f"X{index:04X}{camel_case(sanitize(name))}"


def sub_members(subs: list) -> dict:
    """Member names for (sub-index, ParameterName) pairs in sub-index order: the sanitized
    name, with prefix 's' when it starts with a digit, and '_<sub-index>' appended when the
    name is taken (by an earlier sub-index, a C++ keyword or `item`)."""
    taken = set(RESERVED_MEMBERS)
    names = {}
    for sub, parameter_name in subs:
        base = sanitize(parameter_name) or f"sub{sub}"
        if base[0].isdigit():
            base = "s" + base
        name = base
        while name in taken:
            name = f"{name}_{sub}"
        taken.add(name)
        names[sub] = name
    return names
