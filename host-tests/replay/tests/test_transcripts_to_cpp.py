"""The transcript compiler: the host parser's rules and messages (host-tests/support/
transcript.cpp, targets/linux/frame_text.cpp), the tables it writes, and how it fails a build."""

import contextlib
import io
import os
import tempfile
import unittest

import transcripts_to_cpp as compiler


DEVICES = ["example", "solo", "gra", "grn"]


def parse(text, path="t.transcript"):
    return compiler.parse_transcript(text.encode(), path, DEVICES)


class ParseErrors(unittest.TestCase):
    """Every way a transcript is refused, with the host parser's message and line."""

    def assert_refused(self, text, message):
        with self.assertRaises(compiler.TranscriptError) as caught:
            parse(text)
        self.assertEqual(str(caught.exception), message)

    def test_frames(self):
        cases = [
            ("tx 701", "t.transcript:2: expected '<id> [<dlc>] <bytes>'"),
            ("tx 800 [1] 00", "t.transcript:2: bad identifier '800'"),
            ("tx 20000000 [0]", "t.transcript:2: bad identifier '20000000'"),
            ("tx 70G [1] 00", "t.transcript:2: bad identifier '70G'"),
            ("tx 701 [9] 00", "t.transcript:2: bad length '[9]' (expected [0]..[8])"),
            ("tx 701 1 00", "t.transcript:2: bad length '1' (expected [0]..[8])"),
            ("tx 701 [2] 00", "t.transcript:2: length [2] but 1 data bytes"),
            ("tx 701 [1] 0", "t.transcript:2: bad data byte '0'"),
            ("tx 701 [1] zz", "t.transcript:2: bad data byte 'zz'"),
            ("rx 601 [1] xx", "t.transcript:2: 'xx' is only allowed in expected (tx) frames"),
        ]
        for line, message in cases:
            with self.subTest(line=line):
                self.assert_refused("device example\n" + line, message)

    def test_other_keywords(self):
        cases = [
            ("node-id 0", "t.transcript:2: node-id must be 1..127"),
            ("node-id 128", "t.transcript:2: node-id must be 1..127"),
            ("node-id x", "t.transcript:2: node-id must be 1..127"),
            ("node-id 99999999999", "t.transcript:2: node-id must be 1..127"),
            ("wait", "t.transcript:2: wait needs a number of milliseconds"),
            ("wait -1", "t.transcript:2: wait needs a number of milliseconds"),
            ("wait 99999999999999999999", "t.transcript:2: wait needs a number of milliseconds"),
            ("sim   \t", "t.transcript:2: sim needs a command"),
            ("ignore 800", "t.transcript:2: ignore needs an 11-bit CAN-ID in hex"),
            ("ignore -1", "t.transcript:2: ignore needs an 11-bit CAN-ID in hex"),
            ("ignore 0x", "t.transcript:2: ignore needs an 11-bit CAN-ID in hex"),
            ("ignore g", "t.transcript:2: ignore needs an 11-bit CAN-ID in hex"),
            ("ignore 181 281", "t.transcript:2: ignore takes one CAN-ID (one line each)"),
            ("transmit 701 [1] 00", "t.transcript:2: unknown keyword 'transmit'"),
        ]
        for line, message in cases:
            with self.subTest(line=line):
                self.assert_refused("device example\n" + line, message)

    def test_device(self):
        self.assert_refused("# nothing\ntx 701 [1] 00\n", "t.transcript: no 'device' line")
        self.assert_refused("device\n", "t.transcript: no 'device' line")
        self.assert_refused("device toaster\n",
                            "t.transcript: device 'toaster' cannot be replayed "
                            "(example, solo, gra, grn)")


class Syntax(unittest.TestCase):
    """What the host parser accepts, read the same way."""

    def test_numbers_are_read_as_the_stream_reads_them(self):
        transcript = parse("device gra\nnode-id +3abc\nwait 10ms\nignore 0x1fF\nignore -0\n"
                           "ignore 183 # comment\n")
        self.assertEqual(transcript["node_id"], 3)
        self.assertEqual(transcript["steps"][0]["milliseconds"], 10)
        self.assertEqual(transcript["ignored"], [0x1FF, 0, 0x183])

    def test_frames(self):
        transcript = parse("device example\n"
                           "tx 701 [1] RTR\n"
                           "rx 18FF0001 [2] 01 ab\n"
                           "tx 0701 [3] xx 02 XX\n"
                           "tx 701 [0]\n")
        frames = [step["frame"] for step in transcript["steps"]]
        self.assertEqual(frames[0], (0x701, False, True, 1, [0] * 8, 0))
        self.assertEqual(frames[1], (0x18FF0001, True, False, 2, [1, 0xAB] + [0] * 6, 0))
        self.assertEqual(frames[2], (0x701, True, False, 3, [0, 2] + [0] * 6, 0b101))
        self.assertEqual(frames[3], (0x701, False, False, 0, [0] * 8, 0))

    def test_lines_comments_and_white_space(self):
        transcript = parse("# heading\r\n\n  device   solo  \r\n\ttx 701 [1] 00\r\n"
                           "silence anything\nsim  \traw 1 2 \t # turn\n")
        self.assertEqual(transcript["device"], "solo")
        self.assertEqual([step["line"] for step in transcript["steps"]], [4, 5, 6])
        self.assertEqual([step["kind"] for step in transcript["steps"]], ["tx", "silence", "sim"])
        self.assertEqual(transcript["steps"][2]["command"], b"\traw 1 2")


class Tables(unittest.TestCase):
    """The generated source and the command line."""

    def run_main(self, files, root):
        output = os.path.join(root, "out.cpp")
        errors = io.StringIO()
        with contextlib.redirect_stderr(errors):
            status = compiler.main(["--suite", "demo", "--symbol", "kDemoSuite", "--root", root,
                                    "--output", output, "--devices", ",".join(DEVICES)] + files)
        return status, errors.getvalue(), output

    def test_writes_sorted_scripts_with_every_field(self):
        with tempfile.TemporaryDirectory() as root:
            os.mkdir(os.path.join(root, "demo"))
            paths = []
            for name, text in [("b.transcript", "device grn\nnode-id 5\nsim angle \"9\\0\"\n"),
                               ("a.transcript", "device example\nignore 1FF\ntx 701 [1] xx\n"
                                                "wait 1000\n")]:
                paths.append(os.path.join(root, "demo", name))
                with open(paths[-1], "w", encoding="utf-8") as file:
                    file.write(text)
            status, errors, output = self.run_main(paths, root)
            self.assertEqual((status, errors), (0, ""))
            with open(output, encoding="utf-8") as file:
                source = file.read()
        self.assertLess(source.index('"demo/a.transcript"'), source.index('"demo/b.transcript"'))
        self.assertIn("{StepKind::kTransmit, 3, 0x01, {0x701, "
                      "{0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}, 1, false, false}, 0U, "
                      "nullptr},", source)
        self.assertIn("{StepKind::kWait, 4, 0x00, {0x0, "
                      "{0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}, 0, false, false}, 1000U, "
                      "nullptr},", source)
        self.assertIn('"angle \\"9\\\\0\\""}', source)
        self.assertIn("constexpr uint32_t kIgnored0[] = {0x1FF};", source)
        self.assertIn('{"demo/a.transcript", "example", 1, kSteps0, 2, kIgnored0, 1},',
                      source)
        self.assertIn('{"demo/b.transcript", "grn", 5, kSteps1, 1, nullptr, 0},',
                      source)
        self.assertIn('extern const Suite kDemoSuite = {"demo", kScripts, 2};', source)

    def test_a_bad_transcript_fails_with_its_line_and_writes_nothing(self):
        with tempfile.TemporaryDirectory() as root:
            path = os.path.join(root, "bad.transcript")
            with open(path, "w", encoding="utf-8") as file:
                file.write("device example\n\ntx 701 [1] 0x\n")
            status, errors, output = self.run_main([path], root)
            self.assertFalse(os.path.exists(output))
        self.assertEqual(status, 1)
        self.assertEqual(errors, "error: %s:3: bad data byte '0x'\n" % path)

    def test_an_empty_suite_is_a_table_without_scripts(self):
        with tempfile.TemporaryDirectory() as root:
            status, _, output = self.run_main([], root)
            with open(output, encoding="utf-8") as file:
                source = file.read()
        self.assertEqual(status, 0)
        self.assertIn('extern const Suite kDemoSuite = {"demo", nullptr, 0};', source)


if __name__ == "__main__":
    unittest.main()
