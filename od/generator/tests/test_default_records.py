"""The generated default records (od::DefaultValue) and the bases of objects without RAM values:
what restoring a range of the RAM block relies on."""

import unittest

from tests.helpers import eds, run_text


class DefaultRecordsTest(unittest.TestCase):
    def test_long_defaults_in_pieces_and_bases_of_objects_without_values(self):
        # A default of more than 255 bytes: pieces of at most 255, those of zeros left out. An
        # object without RAM values has the next one's base, the last such sizeof(Values).
        text = "x" * 260
        result = run_text(eds(f"""
            [1000]
            ParameterName=Device type
            DataType=0x0007
            AccessType=const
            [2000]
            ParameterName=Text
            DataType=0x0009
            AccessType=rw
            DefaultValue={text}
            [2001]
            ParameterName=Octets
            DataType=0x000A
            AccessType=rw
            DefaultValue={"00" * 300}01
            [2002]
            ParameterName=Last
            DataType=0x0007
            AccessType=const
            """))
        self.assertEqual(result.status, 0)
        cpp = result.files["test_od.cpp"]
        self.assertIn("{0x0U, offsetof(Values, x2000_text), 255, costa::od::kDefaultInBytes},", cpp)
        self.assertIn("{0xFFU, offsetof(Values, x2000_text) + 255, 6, costa::od::kDefaultInBytes},",
                      cpp)
        self.assertIn("{0x105U, offsetof(Values, x2001_octets) + 255, 46, "
                      "costa::od::kDefaultInBytes},", cpp)
        self.assertNotIn("offsetof(Values, x2001_octets), 255", cpp)  # 255 zeros: no piece
        self.assertIn("{0x1000, costa::od::ObjectCode::kVar, 1, 0, offsetof(Values, x2000_text)},",
                      cpp)
        self.assertIn("{0x2002, costa::od::ObjectCode::kVar, 1, 0, sizeof(Values)},", cpp)

    def test_equal_default_bytes_are_held_once(self):
        # Numbers with bits 16..28 set are bytes of kDefaultBytes; equal ones refer to the same
        # bytes.
        result = run_text(eds("""
            [2000]
            ParameterName=First
            DataType=0x0007
            AccessType=rw
            DefaultValue=0x80010000
            [2001]
            ParameterName=Second
            DataType=0x0007
            AccessType=rw
            DefaultValue=0x80010000
            [2002]
            ParameterName=Small
            DataType=0x0007
            AccessType=rw
            DefaultValue=0xFFFF
            """))
        self.assertEqual(result.status, 0)
        cpp = result.files["test_od.cpp"]
        for name in ("x2000_first", "x2001_second"):
            self.assertIn(f"{{0x0U, offsetof(Values, {name}), 4, costa::od::kDefaultInBytes | "
                          "costa::od::kDefaultNumber},", cpp)
        self.assertIn("{0xFFFFU, offsetof(Values, x2002_small), 4, costa::od::kDefaultNumber},", cpp)
        self.assertIn("constexpr uint8_t kDefaultBytes[] = {\n    0x00, 0x00, 0x01, 0x80,\n};", cpp)

    def test_numbers_with_top_bits_are_held_as_themselves(self):
        # A COB-ID's bits 29..31 above a 16-bit value: the value and kDefaultTopBits, no bytes.
        result = run_text(eds("""
            [2000]
            ParameterName=Invalid
            DataType=0x0007
            AccessType=rw
            DefaultValue=$NODEID+0xC0000180
            [2001]
            ParameterName=Short
            DataType=0x0006
            AccessType=rw
            DefaultValue=0xFFFF
            """))
        self.assertEqual(result.status, 0)
        cpp = result.files["test_od.cpp"]
        self.assertIn("{0x180U, offsetof(Values, x2000_invalid), 4, costa::od::kDefaultNumber | "
                      "costa::od::kDefaultNodeId | costa::od::defaultTopBits(0xC0000000U)},  "
                      "// 0x2000:0 = 0xC0000180", cpp)
        self.assertIn("{0xFFFFU, offsetof(Values, x2001_short), 2, costa::od::kDefaultNumber},", cpp)
        self.assertIn("constexpr uint8_t kDefaultBytes[] = {\n    0,  // none", cpp)


if __name__ == "__main__":
    unittest.main()
