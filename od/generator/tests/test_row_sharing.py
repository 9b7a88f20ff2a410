"""Rows of kRows that objects of different shapes share: a VAR whose one row equals the first
row of a longer run (the sub-index 0 of a record) takes that row."""

import unittest

from tests.helpers import eds, run_text


class RowSharingTest(unittest.TestCase):
    def test_a_var_takes_the_first_row_of_a_record_equal_to_its_row(self):
        result = run_text(eds("""
            [2000]
            ParameterName=Record
            ObjectType=0x9
            SubNumber=2
            [2000sub0]
            ParameterName=Highest sub-index supported
            DataType=0x0005
            AccessType=rw
            DefaultValue=1
            [2000sub1]
            ParameterName=Value
            DataType=0x0007
            AccessType=rw
            [2001]
            ParameterName=Read-only
            DataType=0x0005
            AccessType=ro
            [2002]
            ParameterName=Counter
            DataType=0x0005
            AccessType=rw
            """))
        self.assertEqual(result.status, 0)
        cpp = result.files["test_od.cpp"]
        # The VAR 0x2002 has no row of its own: it takes the record's first.
        self.assertIn("    // 0x2000 Record, 0x2002\n", cpp)
        self.assertNotIn("// 0x2002 Counter", cpp)
        self.assertIn("{0x2002, costa::od::ObjectCode::kVar, 1, 0, offsetof(Values, "
                      "x2002_counter)},", cpp)
        self.assertIn("{0x2000, costa::od::ObjectCode::kRecord, 2, 0, offsetof(Values, "
                      "x2000_record)},", cpp)
        self.assertIn("static_assert(0 == offsetof(Values::X2000Record, "
                      "highest_sub_index_supported), \"0x2002:0 lies where the row it shares "
                      "says\");", cpp)
        # A VAR whose row begins no longer run keeps a row of its own.
        self.assertIn("    // 0x2001 Read-only\n", cpp)
        self.assertIn("{0x2001, costa::od::ObjectCode::kVar, 1, 2, ", cpp)


if __name__ == "__main__":
    unittest.main()
