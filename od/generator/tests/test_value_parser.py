import math
import struct
import unittest

from data_types import DATA_TYPES
from value_parser import parse_default, parse_integer, parse_limit

T = {t.eds_name: t for t in DATA_TYPES.values()}


def default(text, type_name):
    return parse_default(text, T[type_name])


class IntegerTest(unittest.TestCase):
    def test_notations(self):
        self.assertEqual(parse_integer("42"), 42)
        self.assertEqual(parse_integer("0x2A"), 42)
        self.assertEqual(parse_integer("0X2a"), 42)
        self.assertEqual(parse_integer("052"), 42)  # octal, CiA 306
        self.assertEqual(parse_integer("0"), 0)
        self.assertEqual(parse_integer("-42"), -42)
        self.assertEqual(parse_integer("+7"), 7)

    def test_invalid(self):
        for text in ("", "08", "1.5", "0x", "12a", "1 2", "--1", "1_000"):
            with self.subTest(text=text), self.assertRaises(ValueError):
                parse_integer(text)


class DefaultTest(unittest.TestCase):
    def test_integer_ranges(self):
        cases = {
            "INTEGER8": (-128, 127), "INTEGER16": (-32768, 32767),
            "INTEGER32": (-2**31, 2**31 - 1), "INTEGER64": (-2**63, 2**63 - 1),
            "UNSIGNED8": (0, 255), "UNSIGNED16": (0, 65535),
            "UNSIGNED32": (0, 2**32 - 1), "UNSIGNED64": (0, 2**64 - 1),
        }
        for name, (low, high) in cases.items():
            with self.subTest(type=name):
                self.assertEqual(default(str(low), name).value, low)
                self.assertEqual(default(str(high), name).value, high)
                for bad in (low - 1, high + 1):
                    with self.assertRaisesRegex(ValueError, "out of range for " + name):
                        default(str(bad), name)

    def test_integer_notations(self):
        self.assertEqual(default("0x1F", "UNSIGNED16").value, 31)
        self.assertEqual(default("017", "UNSIGNED32").value, 15)
        self.assertEqual(default("-5", "INTEGER8").value, -5)
        self.assertEqual(default(" 12 ", "UNSIGNED8").value, 12)
        with self.assertRaises(ValueError):
            default("0xFF", "INTEGER8")  # hex is a value, not a bit pattern

    def test_empty_is_zero(self):
        for name in ("BOOLEAN", "INTEGER8", "UNSIGNED64"):
            self.assertEqual(default("", name).value, 0)
        self.assertEqual(default("", "REAL32").value, 0.0)
        self.assertEqual(default("", "VISIBLE_STRING").value, b"")
        self.assertEqual(default("", "OCTET_STRING").value, b"")

    def test_node_id_forms(self):
        for text, base in (("$NODEID", 0), ("$NODEID+0x80", 0x80), ("0x80+$NODEID", 0x80),
                           ("$nodeid + 5", 5), (" 5 + $NodeId ", 5), ("$NODEID+017", 15)):
            with self.subTest(text=text):
                parsed = default(text, "UNSIGNED32")
                self.assertEqual(parsed.value, base)
                self.assertTrue(parsed.node_id_relative)
        self.assertFalse(default("0x80", "UNSIGNED32").node_id_relative)

    def test_node_id_misuse(self):
        for text in ("$NODEID-1", "$NODEID*2", "$NODEID+", "x+$NODEID", "$NODEID+$NODEID"):
            with self.subTest(text=text), self.assertRaises(ValueError):
                default(text, "UNSIGNED32")
        for name in ("BOOLEAN", "REAL32", "REAL64", "VISIBLE_STRING", "OCTET_STRING"):
            with self.subTest(type=name), self.assertRaisesRegex(ValueError, r"\$NODEID"):
                default("$NODEID", name)
        with self.assertRaisesRegex(ValueError, "out of range"):
            default("$NODEID+256", "UNSIGNED8")

    def test_boolean(self):
        for text, value in (("0", 0), ("1", 1), ("TRUE", 1), ("false", 0), ("True", 1)):
            self.assertEqual(default(text, "BOOLEAN").value, value)
        for text in ("2", "yes", "-1"):
            with self.assertRaises(ValueError):
                default(text, "BOOLEAN")

    def test_reals(self):
        value = default("0.1", "REAL32").value
        self.assertEqual(value, struct.unpack("<f", struct.pack("<f", 0.1))[0])
        self.assertEqual(default("-2.5e-3", "REAL64").value, -0.0025)
        self.assertEqual(default("5", "REAL64").value, 5.0)
        self.assertEqual(default(".5", "REAL32").value, 0.5)
        for text, name in (("inf", "REAL64"), ("nan", "REAL32"), ("1e400", "REAL64"),
                           ("1e39", "REAL32"), ("0x10", "REAL32"), ("1,5", "REAL64")):
            with self.subTest(text=text), self.assertRaises(ValueError):
                default(text, name)

    def test_strings(self):
        self.assertEqual(default("  Costa device ", "VISIBLE_STRING").value, b"Costa device")
        self.assertEqual(default("01 02 A0", "OCTET_STRING").value, b"\x01\x02\xa0")
        self.assertEqual(default("0102a0", "OCTET_STRING").value, b"\x01\x02\xa0")
        for text in ("012", "0g", "01-02"):
            with self.subTest(text=text), self.assertRaises(ValueError):
                default(text, "OCTET_STRING")

    def test_domain_default_ignored(self):
        self.assertIsNone(default("anything at all", "DOMAIN").value)


class LimitTest(unittest.TestCase):
    def test_limits(self):
        self.assertEqual(parse_limit("-0x10", T["INTEGER16"], "LowLimit"), -16)
        self.assertEqual(parse_limit("1.5", T["REAL64"], "HighLimit"), 1.5)
        with self.assertRaisesRegex(ValueError, r"\$NODEID is not allowed in LowLimit"):
            parse_limit("$NODEID", T["UNSIGNED8"], "LowLimit")
        with self.assertRaisesRegex(ValueError, "out of range"):
            parse_limit("300", T["UNSIGNED8"], "HighLimit")
        self.assertTrue(math.isfinite(parse_limit("3.4e38", T["REAL32"], "HighLimit")))


if __name__ == "__main__":
    unittest.main()
