"""The generated C++ text, the files written and the command line."""

import os
import re
import subprocess
import sys
import tempfile
import unittest
import zlib

from cpp_literals import c_string, float32_literal, integer_literal
from data_types import DATA_TYPES
from tests.helpers import (EXAMPLE_EDS, GENERATOR_DIR, MINIMAL_EDS, eds, generate_example,
                           parse_file, run_generator, run_text)

T = {t.eds_name: t for t in DATA_TYPES.values()}


class ExampleOutputTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.files = generate_example()
        cls.hpp = cls.files["example_od.hpp"]
        cls.cpp = cls.files["example_od.cpp"]
        cls.names = cls.files["example_od_names.cpp"]

    def test_exactly_three_files(self):
        self.assertEqual(sorted(self.files),
                         ["example_od.cpp", "example_od.hpp", "example_od_names.cpp"])

    def test_header_includes_and_namespace(self):
        self.assertEqual(re.findall(r"#include .*", self.hpp),
                         ["#include <stddef.h>", "#include <stdint.h>",
                          '#include "costa/od/definition.hpp"'])
        self.assertIn("#pragma once", self.hpp)
        self.assertIn("namespace costa::gen::example {", self.hpp)
        self.assertIn("extern const costa::od::Definition kDefinition;", self.hpp)
        self.assertIn("extern const costa::od::NameTable kNames;", self.hpp)

    def test_member_naming(self):
        for declaration in (
                "uint16_t x1017_producer_heartbeat_time;",
                "struct X1018IdentityObject {",
                "X1018IdentityObject x1018_identity_object;",
                "uint32_t vendor_id;",
                "uint8_t number_of_errors;",
                "uint32_t item[4];",               # 0x1003 subs 1..4
                "uint16_t default_6;",             # keyword -> _<sub>
                "uint16_t default_7;",             # collision -> _<sub>
                "uint8_t s2nd_value;",             # leading digit -> s
                "uint16_t element_2;",             # mixed array: individual members
                "char item[2][5];",                # string array: capacity 4 + NUL
                "char x2003_serial_text[21];",
                "uint8_t x2004_octets[6];",
                "char x1008_manufacturer_device_name[14];",
                "uint8_t x2005_packed_octets[3];",
                "int16_t item[2];",                # const compact array in Constants
                "struct X1A00Tpdo1MappingParameter {"):
            with self.subTest(declaration=declaration):
                self.assertIn(declaration, self.hpp)
        self.assertNotIn("x2006", self.hpp)  # DOMAINs have no storage
        self.assertNotIn("x2007", self.hpp)

    def test_const_and_ram_split(self):
        values, constants = self.hpp.split("struct Constants {")
        self.assertIn("uint32_t x1000_device_type;", constants)
        self.assertNotIn("x1000_device_type", values)
        self.assertIn("uint16_t element;  // sub 1", constants)
        self.assertNotIn("uint16_t element;", values)

    def test_capacity(self):
        for line in ("static constexpr uint16_t kRpdoCount = 2;",
                     "static constexpr uint16_t kTpdoCount = 1;",
                     "static constexpr uint16_t kLargestValue = 20;",
                     "static constexpr uint8_t kHeartbeatConsumers = 3;",
                     "static constexpr uint8_t kErrorHistory = 4;",
                     "static constexpr uint16_t kObjectCount = 31;"):
            self.assertIn(line, self.hpp)

    def test_sub_entry_rows(self):
        self.assertIn(
            "{0, 1, costa::od::DataType::kUnsigned16, costa::od::kReadable | costa::od::kWritable"
            " | costa::od::kHasLimits, 2, costa::od::kGroupCommunication, 1, 0},", self.cpp)
        self.assertIn("{0x1017, costa::od::ObjectCode::kVar, 1, 11, "
                      "offsetof(Values, x1017_producer_heartbeat_time)},", self.cpp)
        # Record members of one type stored back to back: one row of four.
        self.assertIn(
            "{1, 4, costa::od::DataType::kUnsigned32, costa::od::kReadable | "
            "costa::od::kPlainInteger, 4, "
            "costa::od::kGroupNone, 0, offsetof(Values::X1018IdentityObject, vendor_id)},",
            self.cpp)
        self.assertIn(
            "static_assert(offsetof(Values, x1018_identity_object) + offsetof(Values::"
            "X1018IdentityObject, serial_number) == offsetof(Values, x1018_identity_object) + "
            "offsetof(Values::X1018IdentityObject, vendor_id) + 12U, \"0x1018:4 follows the "
            "value before it\");", self.cpp)
        # Array items: one row of three.
        self.assertIn(
            "{1, 3, costa::od::DataType::kUnsigned32, costa::od::kReadable | costa::od::kWritable"
            " | costa::od::kPlainInteger, 4, costa::od::kGroupCommunication, 0, offsetof(Values::X1016ConsumerHeartbeatTime,"
            " item)},", self.cpp)
        # Strings are never merged: one row per item.
        self.assertIn("+ 1 * sizeof(char[5])},", self.cpp)
        self.assertIn(
            "{0, 1, costa::od::DataType::kUnsigned8, costa::od::kReadable | costa::od::kInRom, 1,"
            " costa::od::kGroupNone, 0, offsetof(Constants, x1018_identity_object) + "
            "offsetof(Constants::X1018IdentityObject, highest_sub_index_supported)},", self.cpp)
        # A ROM row's offset is from the start of the constants block.
        self.assertIn("costa::od::kInRom, 4, costa::od::kGroupNone, 0, offsetof(Constants, "
                      "x1000_device_type)},", self.cpp)
        # An object without RAM values has the base of the next object's.
        self.assertIn("{0x1000, costa::od::ObjectCode::kVar, 1, 0, offsetof(Values, "
                      "x1001_error_register)},", self.cpp)
        self.assertIn("{0, 1, costa::od::DataType::kDomain, costa::od::kReadable | "
                      "costa::od::kWritable, 0, costa::od::kGroupNone, 0, 0},", self.cpp)
        self.assertIn("costa::od::kReadable | costa::od::kWritable | costa::od::kNodeIdRelative"
                      " | costa::od::kPlainInteger, 4, costa::od::kGroupCommunication, 0, 0},", self.cpp)
        self.assertIn("{0x1014, costa::od::ObjectCode::kVar, 1, 8, offsetof(Values, "
                      "x1014_cob_id_emcy)},", self.cpp)
        self.assertIn("costa::od::kGroupLss", self.cpp)
        self.assertIn(", 1, 7, 0, offsetof(Values::X2009LssSettings, custom_group)}", self.cpp)
        # A ROM item and RAM items of one array differ in attributes: separate rows.
        self.assertIn("{2, 2, costa::od::DataType::kUnsigned16, costa::od::kReadable | "
                      "costa::od::kWritable | costa::od::kPlainInteger, 2, costa::od::kGroupApplication, 0, "
                      "offsetof(Values::X2008MixedArray, element_2)},", self.cpp)
        self.assertIn('static_assert(sizeof(Values) <= 0xFFFFU && sizeof(Constants) <= 0xFFFFU, '
                      '"value offsets are 16-bit: keep each block under 64 KiB");', self.cpp)

    def test_objects_sorted(self):
        rows = re.findall(r"\{0x([0-9A-F]{4}), costa::od::ObjectCode::(\w+), (\d+), \d+, ",
                          self.cpp)
        self.assertEqual(len(rows), 31)
        self.assertEqual([r[0] for r in rows], sorted(r[0] for r in rows))
        self.assertIn(("1016", "kArray", "2"), rows)
        self.assertIn(("1018", "kRecord", "2"), rows)
        self.assertIn(("2006", "kDomain", "1"), rows)
        self.assertIn(("1000", "kVar", "1"), rows)

    def test_objects_of_one_shape_share_rows(self):
        # The two RPDO communication parameters: one run of rows (from row 14), each object
        # at its own RAM base, and a check that the second one's values lie where the rows say.
        self.assertIn("    // 0x1400 RPDO1 communication parameter, 0x1401\n", self.cpp)
        self.assertIn("{0x1400, costa::od::ObjectCode::kRecord, 3, 14, offsetof(Values, "
                      "x1400_rpdo1_communication_parameter)},", self.cpp)
        self.assertIn("{0x1401, costa::od::ObjectCode::kRecord, 3, 14, offsetof(Values, "
                      "x1401_rpdo2_communication_parameter)},", self.cpp)
        self.assertIn("static_assert(offsetof(Values::X1401Rpdo2CommunicationParameter, "
                      "cob_id_used_by_rpdo) == offsetof(Values::X1400Rpdo1CommunicationParameter,"
                      " cob_id_used_by_rpdo), \"0x1401:1 lies where the row it shares says\");",
                      self.cpp)
        # Their constants (sub-index 0, 2) are equal: one copy in ROM, the first object's.
        self.assertIn("X1400Rpdo1CommunicationParameter x1400_rpdo1_communication_parameter;",
                      self.hpp)
        self.assertNotIn("x1401_rpdo2_communication_parameter;", self.hpp.split(
            "struct Constants {")[1])
        # Objects of another shape (the TPDO's parameter has five rows) have rows of their own.
        self.assertIn("{0x1800, costa::od::ObjectCode::kRecord, 5, 19, ", self.cpp)

    def test_limits_table(self):
        self.assertIn("{0xFFFFFFFFFFFFFF9CULL, 0x0000000000000064ULL},", self.cpp)  # int8
        self.assertIn("{0xBFF8000000000000ULL, 0x412E848000000000ULL},", self.cpp)  # real32

    def test_default_literals(self):
        # Constants (ROM) as C++ literals.
        for literal in ('"Costa Example",', "{-7, -7},", "{0x01U, 0x02U, 0xA0U},"):
            with self.subTest(literal=literal):
                self.assertIn(literal, self.cpp)
        # RAM defaults: the non-zero ones and the `$NODEID` ones, each with its size and flags;
        # numbers of up to 4 bytes whose bits 16..28 are clear as themselves (bits 29..31 in
        # the flags), the rest (larger numbers, strings, octets) as bytes of kDefaultBytes.
        for record in ("{0x80U, offsetof(Values, x1014_cob_id_emcy), 4, costa::od::kDefaultNumber"
                       " | costa::od::kDefaultNodeId},  // 0x1014:0 = 0x80",
                       "X2000Integers, int16), 2, costa::od::kDefaultNumber},  // 0x2000:2 = 0x8000",
                       "{0x0U, offsetof(Values, x2000_integers) + offsetof(Values::"
                       "X2000Integers, int32), 4, costa::od::kDefaultNumber | "
                       "costa::od::defaultTopBits(0x80000000U)},  // 0x2000:3 = 0x80000000",
                       "X2000Integers, int64), 8, costa::od::kDefaultInBytes | "
                       "costa::od::kDefaultNumber},  // 0x2000:4 = 8 bytes from kDefaultBytes[12]",
                       "{0x20U, offsetof(Values, x2001_real32_value), 4, "
                       "costa::od::kDefaultInBytes | costa::od::kDefaultNumber},",
                       "{0x2CU, offsetof(Values, x2003_serial_text), 21, costa::od::kDefaultInBytes},"
                       "  // 0x2003:0 = 21 bytes from kDefaultBytes[44]",
                       # a `$NODEID` default of 0 has a record: the node-id is added to it
                       "{0x0U, offsetof(Values, x200f_node_id_copy), 2, costa::od::kDefaultNumber"
                       " | costa::od::kDefaultNodeId},"):
            with self.subTest(record=record):
                self.assertIn(record, self.cpp)
        self.assertNotIn("x1001_error_register), 0x", self.cpp)  # default 0: no record
        self.assertIn("0x20, 0x00, 0x01, 0x20, 0x00, 0x00, 0x00, 0x00,\n"
                      "    0x00, 0x00, 0x00, 0x80, 0xFF, 0xFF", self.cpp)
        self.assertIn('static_assert(costa::od::sortedByOffset(kDefaults), "defaults in the '
                      'order of their offsets");', self.cpp)

    def test_definition(self):
        device, _ = parse_file(EXAMPLE_EDS)
        rows = "".join(f"{e.index:04X}.{e.sub:02X}:{e.data_type.code:04X}:{e.size}:{e.group}\n"
                       for e in device.all_entries() if e.group)
        layout = zlib.crc32(rows.encode("ascii"))
        defaults = sum(1 for e in device.all_entries()
                       if not e.in_rom and e.has_storage
                       and (e.node_id_relative or
                            (any(e.default) if isinstance(e.default, bytes) else e.default != 0)))
        self.assertIn("const costa::od::Definition kDefinition = {\n    kObjects,\n    31,\n"
                      "    kRows,\n    &kConstants,\n    kDefaults,\n    kDefaultBytes,\n    "
                      f"{defaults},\n    sizeof(Values),\n"
                      f"    0x{layout:08X}U,\n    \"Costa example device\",\n    kLimits,\n"
                      "    &costa::od::checkLimits,\n    kObjectSlots,\n    26,\n    0x24U,\n};", self.cpp)

    def test_size_checks(self):
        self.assertIn('static_assert(sizeof(Values::x2003_serial_text) == 21, '
                      '"size of 0x2003:0");', self.cpp)
        self.assertIn("static_assert(sizeof(Values::X1003PreDefinedErrorField::item[0]) == 4",
                      self.cpp)
        self.assertIn("static_assert(sizeof(Values::X1003PreDefinedErrorField::item) == 16",
                      self.cpp)

    def test_names(self):
        self.assertIn('{0x1018, 1, "Identity object.Vendor-ID"},', self.names)
        self.assertIn('{0x1000, 0, "Device type"},', self.names)
        self.assertIn('{0x1016, 1, "Consumer heartbeat time.First consumer"},', self.names)
        rows = re.findall(r"\{0x([0-9A-F]{4}), (\d+), \"", self.names)
        keys = [(int(i, 16), int(s)) for i, s in rows]
        self.assertEqual(keys, sorted(keys))
        self.assertIn(f"kNames = {{kNameRows, {len(rows)}}};", self.names)

    def test_no_paths_or_times(self):
        for text in self.files.values():
            self.assertNotIn(GENERATOR_DIR, text)
            self.assertNotIn("/tmp", text)
            self.assertIn("from example.eds.", text.splitlines()[0])


class LayoutIdTest(unittest.TestCase):
    BASE = eds("""
        [1000]
        ParameterName=Device type
        DataType=0x0007
        AccessType=const
        [2000]
        ParameterName=Stored
        DataType={stored}
        AccessType=rw
        [2001]
        ParameterName=Volatile
        DataType={volatile}
        AccessType=ro
        """)

    def layout_id(self, stored, volatile):
        result = run_text(self.BASE.format(stored=stored, volatile=volatile))
        source = result.files["test_od.cpp"]
        return re.search(r"sizeof\(Values\),\n +0x([0-9A-F]{8})U,", source).group(1)

    def test_layout_id_follows_stored_entries_only(self):
        reference = self.layout_id("0x0006", "0x0006")
        self.assertEqual(reference, self.layout_id("0x0006", "0x0007"))
        self.assertNotEqual(reference, self.layout_id("0x0007", "0x0006"))


class SmallOutputTest(unittest.TestCase):
    def test_empty_blocks_get_a_placeholder(self):
        result = run_text(eds("""
            [1000]
            ParameterName=Device type
            DataType=0x0007
            AccessType=const
            """))
        self.assertEqual(result.status, 0)
        header = result.files["test_od.hpp"]
        self.assertIn("struct Values {\n  uint8_t unused_;", header)
        self.assertIn("{0, 0, 0, 0},  // none: keeps the array non-empty", result.files["test_od.cpp"])
        self.assertIn("    kDefaults,\n    kDefaultBytes,\n    0,\n", result.files["test_od.cpp"])
        self.assertIn('"test",', result.files["test_od.cpp"])  # no ProductName
        self.assertIn("kLargestValue = 4;", header)
        self.assertIn("kHeartbeatConsumers = 0;", header)
        self.assertIn("kErrorHistory = 0;", header)
        self.assertNotIn("kLimits", result.files["test_od.cpp"])
        self.assertIn("    nullptr,\n    nullptr,\n    kObjectSlots,\n    29,\n    0x00U,\n};",
                      result.files["test_od.cpp"])

    def test_objects_share_rows_only_with_their_constants(self):
        # Three records of one shape: the first two with the same constant sub-index 0 share it
        # and their rows; the third, whose sub-index 0 differs, has its own copy and its rows.
        record = """
            [{index}]
            ParameterName={name}
            ObjectType=0x9
            SubNumber=2
            [{index}sub0]
            ParameterName=Highest sub-index supported
            DataType=0x0005
            AccessType=const
            DefaultValue={highest}
            [{index}sub1]
            ParameterName=Value
            DataType=0x0007
            AccessType=rw
            """
        result = run_text(eds("".join(record.format(index=i, name=n, highest=h) for i, n, h in
                                      ((2000, "First", 1), (2001, "Same", 1), (2002, "Other", 2)))))
        self.assertEqual(result.status, 0)
        cpp, hpp = result.files["test_od.cpp"], result.files["test_od.hpp"]
        constants = hpp.split("struct Constants {")[1]
        self.assertIn("x2000_first;", constants)
        self.assertNotIn("x2001_same;", constants)
        self.assertIn("x2002_other;", constants)
        self.assertEqual(cpp.count("offsetof(Constants, x2000_first) + offsetof(Constants::"
                                   "X2000First, highest_sub_index_supported)}"), 1)
        self.assertIn("offsetof(Constants, x2002_other) + offsetof(Constants::X2002Other, "
                      "highest_sub_index_supported)}", cpp)
        self.assertIn("{0x2000, costa::od::ObjectCode::kRecord, 2, 0, ", cpp)
        self.assertIn("{0x2001, costa::od::ObjectCode::kRecord, 2, 0, ", cpp)
        self.assertIn("{0x2002, costa::od::ObjectCode::kRecord, 2, 2, ", cpp)

    def test_mappable_constants_keep_their_own_place(self):
        # Equal constants that a TPDO may map are not shared: a PDO tells its entries apart by
        # where their values are.
        var = """
            [{index}]
            ParameterName={name}
            DataType=0x0006
            AccessType=const
            DefaultValue=0x1234
            PDOMapping={mapping}
            """
        result = run_text(eds("".join(var.format(index=i, name=n, mapping=m) for i, n, m in
                                      ((2000, "Mapped", 1), (2001, "Twin", 1), (2002, "Plain", 0),
                                       (2003, "Plain twin", 0)))))
        self.assertEqual(result.status, 0)
        constants = result.files["test_od.hpp"].split("struct Constants {")[1]
        for member in ("x2000_mapped;", "x2001_twin;", "x2002_plain;"):
            with self.subTest(member=member):
                self.assertIn(member, constants)
        self.assertNotIn("x2003_plain_twin;", constants)

    def test_integer_limits_name_the_integer_check_only(self):
        result = run_text(eds("""
            [2000]
            ParameterName=Speed
            DataType=0x0006
            AccessType=rw
            LowLimit=10
            HighLimit=20
            DefaultValue=15
            """))
        self.assertEqual(result.status, 0)
        self.assertIn("    kLimits,\n    &costa::od::checkIntegerLimits,\n    kObjectSlots,",
                      result.files["test_od.cpp"])

    def test_literal_helpers(self):
        self.assertEqual(c_string(b'a"b\\c?\n\x01\xe9'), '"a\\"b\\\\c\\?\\012\\001\\351"')
        self.assertEqual(float32_literal(0.5), "0.5F")
        self.assertEqual(float32_literal(1e20), "1e+20F")
        self.assertEqual(float32_literal(3.0), "3.0F")
        self.assertEqual(integer_literal(-128, T["INTEGER8"]), "-128")
        self.assertEqual(integer_literal(255, T["UNSIGNED8"]), "255U")
        self.assertEqual(integer_literal(5, T["INTEGER64"]), "5LL")


class FilesTest(unittest.TestCase):
    def test_reproducible(self):
        with tempfile.TemporaryDirectory() as first, tempfile.TemporaryDirectory() as second:
            one = run_generator(EXAMPLE_EDS, "example", first)
            two = run_generator(EXAMPLE_EDS, "example", second)
        self.assertEqual(one.status, 0)
        self.assertEqual(one.files, two.files)

    def test_unchanged_files_are_not_rewritten(self):
        with tempfile.TemporaryDirectory() as out:
            self.assertEqual(run_generator(MINIMAL_EDS, "minimal", out).status, 0)
            paths = [os.path.join(out, name) for name in sorted(os.listdir(out))]
            for path in paths:
                os.utime(path, (1000000000, 1000000000))
            self.assertEqual(run_generator(MINIMAL_EDS, "minimal", out).status, 0)
            self.assertEqual([os.stat(p).st_mtime for p in paths], [1000000000.0] * 3)
            self.assertEqual(sorted(os.listdir(out)), [
                "minimal_od.cpp", "minimal_od.hpp", "minimal_od_names.cpp"])

    def test_warnings_do_not_fail(self):
        result = run_text(eds("""
            [2000]
            ParameterName=Value
            DataType=0x0005
            AccessType=rw
            DefaultValue=$NODEID+200
            """))
        self.assertEqual(result.status, 0)
        self.assertEqual(len(result.stderr), 1)
        self.assertRegex(result.stderr[0], r"test\.eds:5: warning: ")
        self.assertEqual(len(result.files), 3)

    def test_errors_leave_existing_outputs_alone(self):
        with tempfile.TemporaryDirectory() as directory:
            path = os.path.join(directory, "bad.eds")
            with open(path, "w", encoding="utf-8") as stream:
                stream.write("[1000]\nParameterName=x\nDataType=0x77\nAccessType=ro\n")
            out = os.path.join(directory, "out")
            result = run_generator(path, "bad", out)
            self.assertEqual(result.status, 1)
            self.assertEqual(result.stderr, [f"{path}:3: error: unknown data type 0x0077"])
            self.assertFalse(os.path.exists(out))

    def test_command_line(self):
        with tempfile.TemporaryDirectory() as out:
            script = os.path.join(GENERATOR_DIR, "costa_odgen.py")
            done = subprocess.run([sys.executable, script, "--eds", MINIMAL_EDS, "--name", "solo",
                                   "--out-dir", out], capture_output=True, text=True)
            self.assertEqual((done.returncode, done.stderr), (0, ""))
            self.assertEqual(sorted(os.listdir(out)),
                             ["solo_od.cpp", "solo_od.hpp", "solo_od_names.cpp"])
            bad = subprocess.run([sys.executable, script, "--eds", MINIMAL_EDS, "--name",
                                  "not-a-name", "--out-dir", out], capture_output=True, text=True)
            self.assertEqual(bad.returncode, 2)
            self.assertIn("not a C++ identifier", bad.stderr)
            missing = subprocess.run([sys.executable, script, "--eds", "/nonexistent.eds",
                                      "--name", "x", "--out-dir", out], capture_output=True,
                                     text=True)
            self.assertEqual(missing.returncode, 1)
            self.assertIn("/nonexistent.eds: error: cannot read", missing.stderr)


if __name__ == "__main__":
    unittest.main()
