import unittest

from diagnostics import Diagnostics
from ini_reader import decode_text, read_ini


def read(text):
    diag = Diagnostics()
    return read_ini(text, diag), diag


class IniReaderTest(unittest.TestCase):
    def test_sections_keys_and_lines(self):
        ini, diag = read("; comment\n[DeviceInfo]\n  ProductName =  My device  \n\n"
                         "[1000]\nDefaultValue=a;b\n")
        self.assertFalse(diag.items)
        info = ini.get("deviceinfo")
        self.assertEqual(info.line, 2)
        self.assertEqual(info.get("PRODUCTNAME").value, "My device")
        self.assertEqual(info.get("productname").line, 3)
        self.assertEqual(ini.get("1000").get("DefaultValue").value, "a;b")

    def test_comment_lines_are_skipped(self):
        ini, diag = read("[S]\n  ; DefaultValue=1\nA=2\n")
        self.assertFalse(diag.items)
        self.assertEqual(list(ini.get("S").entries), ["a"])

    def test_duplicate_section_is_case_insensitive(self):
        _, diag = read("[Sec]\nA=1\n[x]\n[SEC]\nB=2\n")
        self.assertEqual([(d.line, d.severity) for d in diag.items], [(4, "error")])
        self.assertIn("first at line 1", diag.items[0].message)

    def test_duplicate_key_is_case_insensitive(self):
        ini, diag = read("[S]\nKey=1\nkey=2\n")
        self.assertEqual([d.line for d in diag.errors], [3])
        self.assertIn("first at line 2", diag.errors[0].message)
        self.assertEqual(ini.get("S").get("KEY").value, "1")

    def test_malformed_lines(self):
        _, diag = read("A=1\n[S]\nno equals sign\n=value\n[broken\n")
        self.assertEqual([d.line for d in diag.errors], [1, 3, 4, 5])

    def test_crlf_and_bom(self):
        text = decode_text(b"\xef\xbb\xbf[S]\r\nA=1\r\n\r\nB=2\r\n")
        ini, diag = read(text)
        self.assertFalse(diag.items)
        self.assertEqual(ini.get("S").get("B").line, 4)
        self.assertEqual(ini.get("S").get("A").value, "1")

    def test_latin1_fallback(self):
        self.assertEqual(decode_text(b"[S]\nA=\xe9\n"), "[S]\nA=\u00e9\n")


if __name__ == "__main__":
    unittest.main()
