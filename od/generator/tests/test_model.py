"""Semantics of the EDS as the parser builds the model, on the rich fixture and inline files."""

import struct
import unittest

from cpp_literals import limit_pattern
from data_types import (DATA_TYPES, GROUP_APPLICATION, GROUP_COMMUNICATION, GROUP_LSS,
                        GROUP_NONE, OBJECT_ARRAY, OBJECT_DOMAIN, OBJECT_RECORD, OBJECT_VAR)
from tests.helpers import EXAMPLE_EDS, eds, parse_file, parse_text

ATTR = {"R": 1, "W": 2, "ROM": 4, "RPDO": 8, "TPDO": 16, "NODE": 32, "LIM": 64, "PLAIN": 128}


def attrs(*names):
    return sum(ATTR[n] for n in names)


def f32(value):
    return struct.unpack("<f", struct.pack("<f", value))[0]


def var(data_type, access, extra=""):
    return eds(f"""
        [2000]
        ParameterName=Value
        DataType={data_type}
        AccessType={access}
        """) + extra


class ExampleTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.device, cls.diag = parse_file(EXAMPLE_EDS, "example")

    def entry(self, index, sub=0):
        obj = self.device.find(index)
        self.assertIsNotNone(obj, hex(index))
        return obj.entry(sub)

    def test_no_diagnostics(self):
        self.assertEqual(self.diag.items, [])
        self.assertEqual(self.device.product_name, "Costa example device")
        self.assertEqual(len(self.device.objects), 31)
        indices = [o.index for o in self.device.objects]
        self.assertEqual(indices, sorted(indices))

    def test_dummy_usage(self):
        # [DummyUsage]: Dummy0001=0, Dummy0002=1, Dummy0005=1; the others are absent (0).
        self.assertEqual(self.device.dummy_usage, (1 << 2) | (1 << 5))

    def test_object_codes(self):
        self.assertEqual(self.device.find(0x1000).code, OBJECT_VAR)
        self.assertEqual(self.device.find(0x1003).code, OBJECT_ARRAY)
        self.assertEqual(self.device.find(0x1018).code, OBJECT_RECORD)
        self.assertEqual(self.device.find(0x1401).code, OBJECT_RECORD)  # ObjectType=9
        self.assertEqual(self.device.find(0x2006).code, OBJECT_DOMAIN)
        self.assertEqual(self.entry(0x2006).data_type.eds_name, "DOMAIN")
        self.assertEqual(self.entry(0x2007).data_type.eds_name, "DOMAIN")
        self.assertEqual(self.entry(0x2006).size, 0)

    def test_default_forms(self):
        self.assertEqual(self.entry(0x1000).default, 0x191)          # hex
        self.assertEqual(self.entry(0x1401, 2).default, 254)         # octal 0376
        self.assertEqual(self.entry(0x1800, 2).default, 255)         # decimal
        self.assertEqual(self.entry(0x2000, 1).default, -5)          # negative
        self.assertEqual(self.entry(0x2000, 2).default, -32768)
        self.assertEqual(self.entry(0x2000, 3).default, -2**31)
        self.assertEqual(self.entry(0x2000, 4).default, -2**63)
        self.assertEqual(self.entry(0x2000, 5).default, 2**64 - 1)
        self.assertEqual(self.entry(0x2000, 8).default, 1)           # TRUE
        self.assertEqual(self.entry(0x200D).default, 15)             # octal 017
        self.assertEqual(self.entry(0x1001).default, 0)              # missing
        self.assertEqual(self.entry(0x2001).default, f32(3.14159))
        self.assertEqual(self.entry(0x2002).default, -0.0025)
        self.assertEqual(self.entry(0x1008).default, b"Costa Example")
        self.assertEqual(self.entry(0x2003).default, b'Costa "v1"\\?')
        self.assertEqual(self.entry(0x2004).default, b"\x01\x02\xa0\xff")
        self.assertEqual(self.entry(0x2005).default, b"\x01\x02\xa0")
        self.assertEqual(self.entry(0x200B, 2).default, b"")

    def test_node_id_relative_defaults(self):
        for (index, sub), base in {(0x1014, 0): 0x80, (0x1400, 1): 0x200, (0x1401, 1): 0x300,
                                   (0x1800, 1): 0x180, (0x200E, 0): 5,
                                   (0x200F, 0): 0}.items():
            with self.subTest(index=hex(index)):
                entry = self.entry(index, sub)
                self.assertEqual(entry.default, base)
                self.assertTrue(entry.node_id_relative)
        self.assertFalse(self.entry(0x1005).node_id_relative)

    def test_data_types_and_sizes(self):
        sizes = {(0x2000, 8): ("BOOLEAN", 1), (0x2000, 1): ("INTEGER8", 1),
                 (0x2000, 2): ("INTEGER16", 2), (0x2000, 3): ("INTEGER32", 4),
                 (0x2000, 4): ("INTEGER64", 8), (0x1001, 0): ("UNSIGNED8", 1),
                 (0x1017, 0): ("UNSIGNED16", 2), (0x1000, 0): ("UNSIGNED32", 4),
                 (0x2000, 5): ("UNSIGNED64", 8), (0x2001, 0): ("REAL32", 4),
                 (0x2002, 0): ("REAL64", 8), (0x2003, 0): ("VISIBLE_STRING", 20),
                 (0x1008, 0): ("VISIBLE_STRING", 13), (0x2004, 0): ("OCTET_STRING", 6),
                 (0x2005, 0): ("OCTET_STRING", 3), (0x2007, 0): ("DOMAIN", 0)}
        for (index, sub), (type_name, size) in sizes.items():
            with self.subTest(index=hex(index), sub=sub):
                entry = self.entry(index, sub)
                self.assertEqual(entry.data_type.eds_name, type_name)
                self.assertEqual(entry.size, size)

    def test_access_and_pdo_attributes(self):
        expected = {
            (0x1000, 0): attrs("R", "ROM"),
            (0x1001, 0): attrs("R", "TPDO", "PLAIN"),         # ro + PDOMapping
            (0x2000, 1): attrs("R", "W", "RPDO", "TPDO", "LIM"),  # rw + PDOMapping
            (0x2000, 2): attrs("R", "W", "RPDO", "PLAIN"),    # rww + PDOMapping
            (0x2000, 3): attrs("R", "W", "TPDO", "PLAIN"),    # rwr + PDOMapping
            (0x2000, 4): attrs("W", "RPDO", "PLAIN"),         # wo + PDOMapping
            (0x2000, 5): attrs("R", "W", "PLAIN"),            # rw
            (0x2000, 9): attrs("R"),                          # ro BOOLEAN: not an integer
            (0x1014, 0): attrs("R", "W", "NODE", "PLAIN"),
            (0x1017, 0): attrs("R", "W", "LIM"),              # limits: no PLAIN
        }
        for (index, sub), value in expected.items():
            with self.subTest(index=hex(index), sub=sub):
                self.assertEqual(self.entry(index, sub).attributes, value)

    def test_compact_array(self):
        obj = self.device.find(0x1016)
        self.assertEqual([e.sub for e in obj.entries], [0, 1, 2, 3])
        sub0 = obj.entry(0)
        self.assertEqual((sub0.data_type.eds_name, sub0.access, sub0.default),
                         ("UNSIGNED8", "ro", 3))
        for entry in obj.entries[1:]:
            self.assertEqual((entry.data_type.eds_name, entry.access, entry.default),
                             ("UNSIGNED32", "rw", 0))
        self.assertEqual(obj.entry(1).name, "First consumer")  # from [1016Name]
        self.assertEqual(obj.entry(2).name, "Sub2")
        table = self.device.find(0x200A)
        self.assertEqual([e.default for e in table.entries], [2, -7, -7])
        self.assertTrue(all(e.in_rom for e in table.entries[1:]))
        self.assertFalse(table.entry(0).in_rom)

    def test_limits(self):
        int8 = self.entry(0x2000, 1)
        self.assertEqual((int8.low, int8.high), (-100, 100))
        self.assertEqual(limit_pattern(int8.low, int8.data_type), 0xFFFFFFFFFFFFFF9C)
        limited = self.entry(0x2000, 10)
        self.assertEqual(limit_pattern(limited.high, limited.data_type), 0xFFFFFFFFFFFFFFF6)
        real32 = self.entry(0x2001)
        self.assertEqual(limit_pattern(real32.low, real32.data_type), 0xBFF8000000000000)
        self.assertEqual(limit_pattern(real32.high, real32.data_type), 0x412E848000000000)
        real64 = self.entry(0x2002)
        self.assertEqual(limit_pattern(real64.low, real64.data_type),
                         struct.unpack("<Q", struct.pack("<d", -1e300))[0])
        self.assertEqual(limit_pattern(real64.high, real64.data_type), 0)
        self.assertFalse(self.entry(0x2000, 5).has_limits)

    def test_storage_groups(self):
        expected = {
            (0x1000, 0): GROUP_NONE,            # const
            (0x1001, 0): GROUP_NONE,            # ro
            (0x1003, 0): GROUP_NONE,            # rw but 0x1003
            (0x1005, 0): GROUP_COMMUNICATION,
            (0x1010, 1): GROUP_NONE,            # rw but 0x1010
            (0x1016, 0): GROUP_NONE,
            (0x1016, 1): GROUP_COMMUNICATION,
            (0x1400, 1): GROUP_COMMUNICATION,
            (0x2000, 1): GROUP_APPLICATION,
            (0x2000, 4): GROUP_APPLICATION,     # wo
            (0x2000, 9): GROUP_NONE,            # ro
            (0x2006, 0): GROUP_NONE,            # DOMAIN
            (0x2008, 1): GROUP_NONE,            # const element
            (0x2008, 2): GROUP_APPLICATION,
            (0x2009, 0): GROUP_LSS,             # inherits the object's group
            (0x2009, 1): GROUP_LSS,
            (0x2009, 2): 7,                     # numeric override
            (0x2009, 3): GROUP_NONE,            # explicit none
            (0x200C, 0): GROUP_NONE,            # writable but overridden
            (0x200D, 0): GROUP_APPLICATION,     # ro but overridden
        }
        for (index, sub), group in expected.items():
            with self.subTest(index=hex(index), sub=sub):
                self.assertEqual(self.entry(index, sub).group, group)


class InlineTest(unittest.TestCase):
    def parse_ok(self, text):
        device, diag = parse_text(text)
        self.assertFalse(diag.has_errors, [d.message for d in diag.items])
        return device

    def test_every_data_type_code(self):
        for code, data_type in DATA_TYPES.items():
            extra = "CostaStringLength=4\n" if data_type.is_string else ""
            for spelling in (f"0x{code:04X}", str(code)):
                with self.subTest(type=data_type.eds_name, spelling=spelling):
                    device = self.parse_ok(var(spelling, "ro", extra))
                    self.assertIs(device.objects[0].entries[0].data_type, data_type)

    def test_access_types_are_case_insensitive(self):
        for spelling, access in (("RO", "ro"), ("Rw", "rw"), ("RWR", "rwr"), ("CONST", "const"),
                                 ("wo", "wo"), ("rww", "rww")):
            device = self.parse_ok(var("0x0005", spelling))
            self.assertEqual(device.objects[0].entries[0].access, access)

    def test_object_type_defaults_to_var_and_accepts_decimal(self):
        self.assertEqual(self.parse_ok(var("0x0005", "ro")).objects[0].code, OBJECT_VAR)
        device = self.parse_ok(var("0x0005", "ro", "ObjectType=7\n"))
        self.assertEqual(device.objects[0].code, OBJECT_VAR)

    def test_single_limit_takes_the_type_bound(self):
        entry = self.parse_ok(var("0x0003", "rw", "LowLimit=-5\n")).objects[0].entries[0]
        self.assertEqual((entry.low, entry.high), (-5, 32767))
        entry = self.parse_ok(var("0x0008", "rw", "HighLimit=2.5\n")).objects[0].entries[0]
        self.assertEqual(entry.high, 2.5)
        self.assertEqual(entry.low, -f32(3.4028234663852886e38))

    def test_empty_limits_are_absent(self):
        entry = self.parse_ok(var("0x0005", "rw", "LowLimit=\nHighLimit=\n")).objects[0]
        self.assertFalse(entry.entries[0].has_limits)

    def test_string_capacity(self):
        entry = self.parse_ok(var("0x0009", "ro", "DefaultValue=abc\n")).objects[0].entries[0]
        self.assertEqual(entry.size, 3)
        entry = self.parse_ok(var("0x0009", "ro")).objects[0].entries[0]
        self.assertEqual(entry.size, 0)  # read-only and empty: allowed
        entry = self.parse_ok(var("0x0009", "rw", "CostaStringLength=8\n")).objects[0]
        self.assertEqual(entry.entries[0].size, 8)

    def test_const_entry_with_explicit_none_group(self):
        device = self.parse_ok(var("0x0005", "const", "CostaStorageGroup=NONE\n"))
        self.assertEqual(device.objects[0].entries[0].group, GROUP_NONE)

    def test_group_names(self):
        for text, group in (("Application", 2), ("lss", 3), ("4", 4), ("31", 31)):
            device = self.parse_ok(var("0x0005", "rw", f"CostaStorageGroup={text}\n"))
            self.assertEqual(device.objects[0].entries[0].group, group)
        device = self.parse_ok(var("0x0005", "rw", "CostaStorageGroup=communication\n")
                               .replace("[2000]", "[1F00]"))
        self.assertEqual(device.objects[0].entries[0].group, 1)

    def test_product_name_falls_back_to_name(self):
        device, _ = parse_text(var("0x0005", "ro"), "solo")
        self.assertEqual(device.product_name, "solo")

    def test_dummy_usage(self):
        self.assertEqual(self.parse_ok(var("0x0005", "ro")).dummy_usage, 0)  # no section
        every = "".join(f"Dummy{t:04X}={1 if t > 1 else 0}\n" for t in range(1, 8))
        device = self.parse_ok(var("0x0005", "ro", "\n[DummyUsage]\n" + every))
        self.assertEqual(device.dummy_usage, 0xFC)  # 0x0002..0x0007
        device = self.parse_ok(var("0x0005", "ro", "\n[dummyusage]\ndummy0007=0x1\n"))
        self.assertEqual(device.dummy_usage, 0x80)


if __name__ == "__main__":
    unittest.main()
