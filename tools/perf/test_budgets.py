"""Tests of the budget checker (budgets.py) and of the net rule (hot_paths.py).

    python3 -m unittest discover -s tools/perf -t tools/perf     (ctest: check_budgets)

The checker is run as tools/check-budgets runs it, on files written here, so that what is
tested is its verdict and exit status: a budget lowered by one instruction or byte fails, and
names its row.
"""
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import budgets  # noqa: E402
import hot_paths  # noqa: E402

REPOSITORY_BUDGETS = os.path.join(HERE, "..", "budgets.txt")
OPERATIONS = ("idle", "sdo_upload_1017", "sdo_download_1017", "sdo_segmented_upload_20",
              "rpdo_2x32", "rpdo_8x8", "sync_4_tpdos")

BUDGETS = """\
# a comment
instructions idle                 19
instructions sdo_upload_1017     631   # trailing comment

image cortex-m0plus footprint-a 19004 4212
"""
MEASURED = [("instructions idle", 19), ("instructions sdo_upload_1017", 631),
            ("cortex-m0plus footprint-a flash", 19004), ("cortex-m0plus footprint-a RAM", 4212)]


class CheckerTest(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.TemporaryDirectory()
        self.budgets = os.path.join(self.directory.name, "budgets.txt")
        self.measured = os.path.join(self.directory.name, "measured.tsv")

    def tearDown(self):
        self.directory.cleanup()

    def run_checker(self, budget_text, measured, command="check"):
        with open(self.budgets, "w", encoding="utf-8") as out:
            out.write(budget_text)
        with open(self.measured, "w", encoding="utf-8") as out:
            out.write("".join(f"{name}\t{value}\n" for name, value in measured))
        return subprocess.run([sys.executable, os.path.join(HERE, "budgets.py"), command,
                               self.budgets, self.measured], capture_output=True, text=True)

    def test_numbers_equal_to_their_budgets_pass(self):
        result = self.run_checker(BUDGETS, MEASURED)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("| instructions sdo_upload_1017 | 631 | 631 | ok |", result.stdout)
        self.assertIn("| cortex-m0plus footprint-a flash | 19,004 | 19,004 | ok |", result.stdout)

    def test_an_instruction_budget_lowered_by_one_fails_and_names_its_row(self):
        result = self.run_checker(BUDGETS.replace("631", "630"), MEASURED)
        self.assertEqual(result.returncode, 1)
        self.assertIn("FAIL instructions sdo_upload_1017: 631 exceeds its budget of 630",
                      result.stderr)
        self.assertIn("| instructions sdo_upload_1017 | 631 | 630 | FAIL: 1 over |", result.stdout)
        self.assertEqual(result.stderr.count("FAIL"), 1)

    def test_a_flash_budget_lowered_by_one_fails(self):
        result = self.run_checker(BUDGETS.replace("19004", "19003"), MEASURED)
        self.assertEqual(result.returncode, 1)
        self.assertIn("FAIL cortex-m0plus footprint-a flash: 19,004 exceeds its budget of 19,003",
                      result.stderr)

    def test_a_ram_budget_lowered_by_one_fails(self):
        result = self.run_checker(BUDGETS.replace("4212", "4211"), MEASURED)
        self.assertEqual(result.returncode, 1)
        self.assertIn("FAIL cortex-m0plus footprint-a RAM: 4,212 exceeds its budget of 4,211",
                      result.stderr)

    def test_a_number_under_its_budget_passes(self):
        result = self.run_checker(BUDGETS.replace("631", "700"), MEASURED)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("| instructions sdo_upload_1017 | 631 | 700 | ok, 69 under |", result.stdout)

    def test_a_measured_row_without_a_budget_fails(self):
        result = self.run_checker(BUDGETS, MEASURED + [("cortex-m4 example flash", 1)])
        self.assertEqual(result.returncode, 1)
        self.assertIn("FAIL cortex-m4 example flash: measured 1, no budget", result.stderr)

    def test_a_budget_that_was_not_measured_fails(self):
        result = self.run_checker(BUDGETS, MEASURED[1:])
        self.assertEqual(result.returncode, 1)
        self.assertIn("FAIL instructions idle: has a budget but was not measured", result.stderr)

    def test_a_malformed_budget_line_is_an_error(self):
        result = self.run_checker(BUDGETS + "instructions rpdo_2x32\n", MEASURED)
        self.assertEqual(result.returncode, 2)
        self.assertIn("budgets.txt:6: not 'instructions OPERATION N'", result.stderr)

    def test_a_second_budget_for_a_row_is_an_error(self):
        result = self.run_checker(BUDGETS + "instructions idle 20\n", MEASURED)
        self.assertEqual(result.returncode, 2)
        self.assertIn("a second budget for 'instructions idle'", result.stderr)

    def test_update_sets_budgets_to_the_measured_numbers_and_adds_new_rows(self):
        measured = [("instructions idle", 17), ("instructions sdo_upload_1017", 631),
                    ("cortex-m0plus footprint-a flash", 18000),
                    ("cortex-m0plus footprint-a RAM", 4212), ("instructions rpdo_8x8", 900)]
        result = self.run_checker(BUDGETS, measured, command="update")
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(self.budgets, encoding="utf-8") as updated:
            text = updated.read()
        self.assertIn("# a comment\n", text)
        self.assertIn("# trailing comment", text)
        self.assertEqual(budgets.read_budgets(self.budgets), dict(measured))
        self.assertEqual(self.run_checker(text, measured).returncode, 0)

    def test_the_check_of_the_checker_finds_a_checker_that_lets_a_row_through(self):
        self.assertEqual(budgets.self_check(MEASURED), [])
        original = budgets.check
        try:
            budgets.check = lambda limits, measured: (original(limits, measured)[0], [])
            self.assertEqual(len(budgets.self_check(MEASURED)), 3)
        finally:
            budgets.check = original

    def test_measured_instructions_are_rounded_half_up(self):
        self.assertEqual([budgets.whole(n) for n in (631.4, 631.5, 631.6)], [631, 632, 632])


class RepositoryBudgetsTest(unittest.TestCase):
    def test_every_operation_and_both_configurations_have_budgets(self):
        rows = budgets.read_budgets(REPOSITORY_BUDGETS)
        for operation in OPERATIONS:
            self.assertIn(f"instructions {operation}", rows)
        for tree in ("cortex-m4", "cortex-m0plus"):
            for config in ("a", "b"):
                self.assertIn(f"{tree} footprint-{config} flash", rows)
                self.assertIn(f"{tree} footprint-{config} RAM", rows)


class NetRuleTest(unittest.TestCase):
    ROWS = [hot_paths.Row("empty", "loop", 0, 5.0), hot_paths.Row("idle", "cycle", 0, 24.0),
            hot_paths.Row("two_frames", "op", 2, 105.0)]

    def test_net_subtracts_the_loop_and_one_idle_cycle_per_request_frame(self):
        self.assertEqual(hot_paths.net(self.ROWS),
                         [("idle", "cycle", 19.0), ("two_frames", "op", 62.0)])

    def test_the_net_rule_needs_the_empty_operation(self):
        with self.assertRaises(ValueError):
            hot_paths.net(self.ROWS[1:])

    def test_a_qemu_report_becomes_instructions(self):
        report = ("hot-paths 1000\ncalibration 1000 50\ncalibration 1001000 50050\n"
                  "op empty 0 125\nop idle 0 600\nop two_frames 2 2625\n")
        # 40 instructions per tick: empty 5, idle 24, two_frames 105 per run.
        self.assertEqual(hot_paths.from_qemu(report),
                         [("idle", "idle", 19.0), ("two_frames", "two_frames", 62.0)])

    def test_a_qemu_report_without_icount_is_refused(self):
        report = ("hot-paths 1000\ncalibration 1000 50\ncalibration 1001000 47000\n"
                  "op empty 0 125\nop idle 0 600\n")
        with self.assertRaisesRegex(ValueError, "not a whole number"):
            hot_paths.from_qemu(report)

    def test_a_failed_check_in_the_firmware_is_an_error(self):
        with self.assertRaisesRegex(ValueError, "rpdo_2x32"):
            hot_paths.from_qemu("hot-paths 1000\nerror rpdo_2x32 wrong values\n")


if __name__ == "__main__":
    unittest.main()
