"""Every EDS error is reported as FILE:LINE: error: MESSAGE with the line of the problem, the
exit status is 1 and nothing is written."""

import re
import unittest

from tests.helpers import BASE, eds, line_of, run_text

_DIAGNOSTIC = re.compile(r"^(.*):(\d+): (error|warning): (.*)$")


class ErrorTestCase(unittest.TestCase):
    def diagnostics(self, text, expect_failure=True):
        result = run_text(text)
        parsed = []
        for line in result.stderr:
            match = _DIAGNOSTIC.match(line)
            self.assertIsNotNone(match, f"unexpected stderr line: {line}")
            self.assertTrue(match.group(1).endswith("test.eds"))
            parsed.append((int(match.group(2)), match.group(3), match.group(4)))
        if expect_failure:
            self.assertEqual(result.status, 1, result.stderr)
            self.assertEqual(result.files, {}, "no file may be written on errors")
        return parsed

    def assertError(self, text, line, fragment):
        """Exactly one error, at `line`, whose message contains `fragment`."""
        errors = [(n, m) for n, severity, m in self.diagnostics(text) if severity == "error"]
        self.assertEqual(len(errors), 1, errors)
        self.assertEqual(errors[0][0], line, errors)
        self.assertIn(fragment, errors[0][1])


class StructureErrors(ErrorTestCase):
    def test_duplicate_index(self):
        text = BASE + eds("""
            [1001]
            ParameterName=Error register
            DataType=0x0005
            AccessType=ro
            [1001]
            ParameterName=Again
            """)
        self.assertEqual(line_of(text, "[1001]", 2), 13)
        self.assertError(text, 13, "duplicate section [1001] (first at line 9)")

    def test_duplicate_index_spelled_differently(self):
        text = BASE + eds("""
            [00A0]
            ParameterName=A
            DataType=5
            AccessType=ro
            [a0]
            ParameterName=B
            DataType=5
            AccessType=ro
            """)
        self.assertError(text, line_of(text, "[a0]"), "duplicate object 0x00A0 (first at line 9)")

    def test_duplicate_key(self):
        text = BASE + eds("""
            [1001]
            ParameterName=Error register
            DataType=0x0005
            accesstype=ro
            AccessType=rw
            """)
        self.assertError(text, 13, "duplicate key 'AccessType' in [1001] (first at line 12)")

    def test_duplicate_sub_index(self):
        text = BASE + eds("""
            [1018]
            ParameterName=Identity
            ObjectType=0x9
            SubNumber=1
            [1018sub0]
            ParameterName=Highest
            DataType=0x0005
            AccessType=ro
            [1018sub00]
            ParameterName=Again
            """)
        self.assertError(text, line_of(text, "[1018sub00]"), "duplicate sub-index")

    def test_index_zero(self):
        self.assertError(BASE + "[0000]\nParameterName=x\n", 9, "index 0x0000")

    def test_sub_index_ff_reserved(self):
        text = BASE + eds("""
            [1018]
            ParameterName=Identity
            ObjectType=0x9
            SubNumber=1
            [1018sub0]
            ParameterName=Highest
            DataType=0x0005
            AccessType=ro
            [1018subFF]
            ParameterName=Reserved
            """)
        self.assertError(text, line_of(text, "[1018subFF]"), "sub-index 0xFF is reserved")

    def test_var_with_sub_sections(self):
        text = BASE + "[1000sub1]\nParameterName=x\n"
        self.assertError(text, 9, "cannot have sub-index sections")

    def test_sub_section_without_object(self):
        text = BASE + "[2000sub0]\nParameterName=x\n"
        self.assertError(text, 9, "has no object section [2000]")

    def test_missing_sub_index_0(self):
        text = BASE + eds("""
            [1018]
            ParameterName=Identity
            ObjectType=0x9
            SubNumber=1
            [1018sub1]
            ParameterName=Vendor-ID
            DataType=0x0007
            AccessType=ro
            """)
        self.assertError(text, 9, "missing sub-index 0")

    def test_sub_number_mismatch(self):
        text = BASE + eds("""
            [1018]
            ParameterName=Identity
            ObjectType=0x9
            SubNumber=3
            [1018sub0]
            ParameterName=Highest
            DataType=0x0005
            AccessType=ro
            DefaultValue=1
            [1018sub1]
            ParameterName=Vendor-ID
            DataType=0x0007
            AccessType=ro
            """)
        self.assertError(text, 12, "SubNumber=3 but 2 sub-index sections are present")

    def test_missing_sub_number(self):
        text = BASE + eds("""
            [1018]
            ParameterName=Identity
            ObjectType=0x9
            [1018sub0]
            ParameterName=Highest
            DataType=0x0005
            AccessType=ro
            """)
        self.assertError(text, 9, "missing SubNumber")

    def test_sub_index_0_must_be_unsigned8(self):
        text = BASE + eds("""
            [1018]
            ParameterName=Identity
            ObjectType=0x9
            SubNumber=1
            [1018sub0]
            ParameterName=Highest
            DataType=0x0006
            AccessType=ro
            """)
        self.assertError(text, 15, "must be UNSIGNED8")

    def test_compact_with_sub_sections(self):
        text = BASE + eds("""
            [1016]
            ParameterName=Consumer heartbeat time
            ObjectType=0x8
            CompactSubObj=2
            DataType=0x0007
            AccessType=rw
            [1016sub0]
            ParameterName=Highest
            """)
        self.assertError(text, line_of(text, "[1016sub0]"), "together with CompactSubObj")

    def test_compact_on_record(self):
        text = BASE + eds("""
            [1016]
            ParameterName=Record
            ObjectType=0x9
            CompactSubObj=2
            DataType=0x0007
            AccessType=rw
            """)
        self.assertError(text, 12, "only allowed on an ARRAY")

    def test_unsupported_object_type(self):
        self.assertError(BASE + "[1001]\nParameterName=x\nObjectType=0x5\n", 11,
                         "unsupported ObjectType 0x5")

    def test_missing_keys(self):
        self.assertError(BASE + "[1001]\nDataType=5\nAccessType=ro\n", 9,
                         "missing ParameterName")
        self.assertError(BASE + "[1001]\nParameterName=x\nAccessType=ro\n", 9,
                         "missing DataType")
        self.assertError(BASE + "[1001]\nParameterName=x\nDataType=5\n", 9,
                         "missing AccessType")

    def test_no_objects(self):
        self.assertError("[DeviceInfo]\nProductName=x\n", 1, "defines no objects")

    def test_syntax_error(self):
        self.assertError(BASE + "this is no key\n", 9, "expected 'Key=Value'")


class DummyUsageErrors(ErrorTestCase):
    def test_value_other_than_0_or_1(self):
        text = BASE + eds("""
            [DummyUsage]
            Dummy0003=2
            """)
        self.assertError(text, line_of(text, "Dummy0003=2"), "Dummy0003=2: 0 or 1")

    def test_one_bit_dummy(self):
        text = BASE + eds("""
            [DummyUsage]
            Dummy0001=1
            Dummy0002=1
            """)
        self.assertError(text, line_of(text, "Dummy0001=1"), "one-bit dummy entry")

    def test_not_a_number(self):
        text = BASE + eds("""
            [DummyUsage]
            Dummy0004=yes
            """)
        self.assertError(text, line_of(text, "Dummy0004=yes"), "Dummy0004")


class EntryErrors(ErrorTestCase):
    def entry(self, keys):
        """BASE plus object 0x2000 whose keys start on line 10."""
        return BASE + "[2000]\nParameterName=Value\n" + eds(keys)

    def test_unknown_type(self):
        self.assertError(self.entry("DataType=0x0030\nAccessType=rw\n"), 11,
                         "unknown data type 0x0030")
        self.assertError(self.entry("AccessType=rw\nDataType=0x10\n"), 12,
                         "unknown data type 0x0010")
        self.assertError(self.entry("DataType=seven\nAccessType=rw\n"), 11, "invalid integer")

    def test_unknown_access(self):
        self.assertError(self.entry("DataType=0x0007\nAccessType=readwrite\n"), 12,
                         "unknown access type 'readwrite'")

    def test_pdo_mapping_must_be_0_or_1(self):
        self.assertError(self.entry("DataType=7\nAccessType=rw\nPDOMapping=2\n"), 13,
                         "PDOMapping must be 0 or 1")

    def test_value_out_of_type_range(self):
        self.assertError(self.entry("DataType=0x0005\nAccessType=rw\nDefaultValue=256\n"), 13,
                         "default 256 is out of range for UNSIGNED8 (0..255)")
        self.assertError(self.entry("DataType=0x0002\nAccessType=rw\nDefaultValue=-129\n"), 13,
                         "out of range for INTEGER8")
        self.assertError(self.entry("DataType=0x0007\nAccessType=rw\nDefaultValue=-1\n"), 13,
                         "out of range for UNSIGNED32")
        self.assertError(self.entry("DataType=0x0005\nAccessType=rw\nLowLimit=0\n"
                                    "HighLimit=0x100\n"), 14, "HighLimit 256 is out of range")

    def test_default_outside_limits(self):
        self.assertError(self.entry("DataType=0x0006\nAccessType=rw\nLowLimit=10\n"
                                    "DefaultValue=5\nHighLimit=20\n"), 14,
                         "default outside limits")
        self.assertError(self.entry("DataType=0x0004\nAccessType=rw\nDefaultValue=-21\n"
                                    "LowLimit=-20\n"), 13, "default outside limits")
        self.assertError(self.entry("DataType=0x0008\nAccessType=rw\nDefaultValue=1.5\n"
                                    "HighLimit=1.25\n"), 13, "default outside limits")
        # No DefaultValue: the implicit 0 is checked and reported at the section.
        self.assertError(self.entry("DataType=0x0006\nAccessType=rw\nLowLimit=1\n"), 9,
                         "default outside limits")

    def test_low_above_high(self):
        self.assertError(self.entry("DataType=0x0006\nAccessType=rw\nLowLimit=20\n"
                                    "HighLimit=10\n"), 13, "greater than HighLimit")

    def test_limits_on_non_numeric_type(self):
        self.assertError(self.entry("DataType=0x0009\nAccessType=ro\nDefaultValue=a\n"
                                    "HighLimit=10\n"), 14, "only allowed on numeric types")

    def test_node_id_misuse(self):
        self.assertError(self.entry("DataType=0x0008\nAccessType=rw\nDefaultValue=$NODEID\n"),
                         13, "$NODEID is not allowed in a REAL32 default")
        self.assertError(self.entry("DataType=0x0001\nAccessType=rw\nDefaultValue=$NODEID\n"),
                         13, "$NODEID is not allowed in a BOOLEAN default")
        self.assertError(self.entry("DataType=0x0007\nAccessType=rw\nLowLimit=$NODEID+1\n"),
                         13, "$NODEID is not allowed in LowLimit")
        self.assertError(self.entry("DataType=0x0007\nAccessType=rw\nHighLimit=$NODEID\n"),
                         13, "$NODEID is not allowed in HighLimit")
        self.assertError(self.entry("DataType=0x0007\nAccessType=rw\n"
                                    "DefaultValue=$NODEID-1\n"), 13, "invalid $NODEID expression")

    def test_node_id_overflow_is_a_warning(self):
        found = self.diagnostics(self.entry("DataType=0x0005\nAccessType=rw\n"
                                            "DefaultValue=$NODEID+200\n"), expect_failure=False)
        self.assertEqual(found[0][:2], (13, "warning"))

    def test_not_finite_real(self):
        self.assertError(self.entry("DataType=0x0011\nAccessType=rw\nDefaultValue=1e999\n"), 13,
                         "not a finite REAL64")
        self.assertError(self.entry("DataType=0x0008\nAccessType=rw\nDefaultValue=inf\n"), 13,
                         "invalid REAL32 default")

    def test_invalid_octets(self):
        self.assertError(self.entry("DataType=0x000A\nAccessType=ro\nDefaultValue=0 1 2\n"), 13,
                         "invalid OCTET_STRING")

    def test_string_capacity(self):
        self.assertError(self.entry("DataType=0x0009\nAccessType=rw\n"), 9,
                         "writable string needs CostaStringLength")
        self.assertError(self.entry("DataType=0x0009\nAccessType=rw\nDefaultValue=abcdef\n"
                                    "CostaStringLength=4\n"), 14, "shorter than the default")
        self.assertError(self.entry("DataType=0x0007\nAccessType=rw\nCostaStringLength=4\n"),
                         13, "only allowed on VISIBLE_STRING and OCTET_STRING")
        self.assertError(self.entry("DataType=0x000A\nAccessType=ro\n"), 9,
                         "empty OCTET_STRING needs CostaStringLength")
        self.assertError(self.entry("DataType=0x0009\nAccessType=ro\n"
                                    "CostaStringLength=70000\n"), 13, "outside 0..65535")

    def test_storage_group(self):
        self.assertError(self.entry("DataType=7\nAccessType=const\n"
                                    "CostaStorageGroup=application\n"), 13,
                         "const entry cannot be stored")
        self.assertError(self.entry("DataType=7\nAccessType=rw\nCostaStorageGroup=3\n"), 13,
                         "invalid CostaStorageGroup '3'")
        self.assertError(self.entry("DataType=7\nAccessType=rw\nCostaStorageGroup=32\n"), 13,
                         "invalid CostaStorageGroup '32'")
        self.assertError(self.entry("DataType=7\nAccessType=rw\nCostaStorageGroup=often\n"), 13,
                         "invalid CostaStorageGroup")
        self.assertError(self.entry("DataType=0xF\nAccessType=rw\nCostaStorageGroup=lss\n"), 13,
                         "DOMAIN has no stored value")
        self.assertError(self.entry("DataType=7\nAccessType=rw\n"
                                    "CostaStorageGroup=communication\n"), 13,
                         "only an entry of 0x1000..0x1FFF can be in the communication group")
        self.assertError(BASE + "[1F00]\nParameterName=Value\n" +
                         eds("DataType=7\nAccessType=rw\nCostaStorageGroup=application\n"), 13,
                         "an entry below 0x2000 cannot be in the application or a custom group")
        self.assertError(BASE + "[1F00]\nParameterName=Value\n" +
                         eds("DataType=7\nAccessType=rw\nCostaStorageGroup=5\n"), 13,
                         "an entry below 0x2000 cannot be in the application or a custom group")
        self.assertError(BASE + "[1F00]\nParameterName=Record\nObjectType=0x9\n"
                         "CostaStorageGroup=application\nSubNumber=2\n"
                         "[1F00sub0]\nParameterName=Highest\nDataType=0x0005\n"
                         "AccessType=const\nDefaultValue=1\n"
                         "[1F00sub1]\nParameterName=Value\nDataType=0x0007\nAccessType=rw\n",
                         12, "an entry below 0x2000 cannot be in the application or a custom")

    def test_domain_object_with_other_type(self):
        self.assertError(self.entry("ObjectType=0x2\nDataType=0x0007\nAccessType=rw\n"), 12,
                         "DOMAIN object must have DataType DOMAIN")


class ListErrors(ErrorTestCase):
    def lists(self, mandatory, extra=""):
        return eds(f"""
            [MandatoryObjects]
            {mandatory}
            [1000]
            ParameterName=Device type
            DataType=0x0007
            AccessType=const
            [1001]
            ParameterName=Error register
            DataType=0x0005
            AccessType=ro
            """) + extra

    def test_consistent_lists_pass(self):
        found = self.diagnostics(self.lists("SupportedObjects=2\n1=0x1000\n2=0x1001"),
                                 expect_failure=False)
        self.assertEqual(found, [])

    def test_listed_object_without_section(self):
        text = self.lists("SupportedObjects=3\n1=0x1000\n2=0x1001\n3=0x1018")
        self.assertError(text, 5, "object 0x1018 is listed but has no section [1018]")

    def test_section_not_listed(self):
        text = self.lists("SupportedObjects=1\n1=0x1000")
        self.assertError(text, line_of(text, "[1001]"), "object 0x1001 is not listed")

    def test_count_mismatch(self):
        text = self.lists("SupportedObjects=3\n1=0x1000\n2=0x1001")
        self.assertError(text, 2, "SupportedObjects=3 but 2 objects are listed")

    def test_entry_number_outside_count(self):
        text = self.lists("SupportedObjects=2\n1=0x1000\n3=0x1001")
        self.assertError(text, 4, "entry 3 is outside 1..SupportedObjects (2)")

    def test_listed_twice(self):
        text = self.lists("SupportedObjects=2\n1=0x1000\n2=0x1001",
                          "[OptionalObjects]\nSupportedObjects=1\n1=0x1000\n")
        self.assertError(text, line_of(text, "1=0x1000", 2), "listed twice (first at line 3)")

    def test_missing_supported_objects(self):
        text = self.lists("1=0x1000\n2=0x1001")
        self.assertError(text, 1, "missing SupportedObjects")

    def test_all_errors_are_reported(self):
        text = self.lists("SupportedObjects=1\n1=0x1000",
                          "[2000]\nParameterName=x\nDataType=0x99\nAccessType=ro\n")
        errors = [(n, m) for n, s, m in self.diagnostics(text) if s == "error"]
        self.assertEqual([n for n, _ in errors], sorted(n for n, _ in errors))
        self.assertEqual(len(errors), 3, errors)  # 0x1001 and 0x2000 unlisted, bad type


if __name__ == "__main__":
    unittest.main()
