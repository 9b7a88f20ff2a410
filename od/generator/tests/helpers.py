"""Shared helpers of the generator tests."""

import contextlib
import io
import os
import tempfile
import textwrap
from dataclasses import dataclass

import costa_odgen
from diagnostics import Diagnostics
from eds_parser import parse_eds
from ini_reader import read_ini

TESTS_DIR = os.path.dirname(os.path.abspath(__file__))
DATA_DIR = os.path.join(TESTS_DIR, "data")
GENERATOR_DIR = os.path.dirname(TESTS_DIR)
REPO_ROOT = os.path.dirname(os.path.dirname(GENERATOR_DIR))
INCLUDE_DIR = os.path.join(REPO_ROOT, "od", "include")
EXAMPLE_EDS = os.path.join(DATA_DIR, "example.eds")
MINIMAL_EDS = os.path.join(DATA_DIR, "minimal.eds")


def eds(text: str) -> str:
    """An inline EDS: dedented, first line of the text is line 1."""
    return textwrap.dedent(text).lstrip("\n")


def line_of(text: str, needle: str, occurrence: int = 1) -> int:
    """1-based number of the line of `text` equal to `needle` (after trimming)."""
    seen = 0
    for number, line in enumerate(text.split("\n"), start=1):
        if line.strip() == needle:
            seen += 1
            if seen == occurrence:
                return number
    raise AssertionError(f"line {needle!r} not in the EDS")


def parse_text(text: str, name: str = "test"):
    """(Device, Diagnostics) of an inline EDS."""
    diag = Diagnostics()
    device = parse_eds(read_ini(text, diag), diag, name)
    return device, diag


def parse_file(path: str, name: str = "test"):
    with open(path, encoding="utf-8") as stream:
        return parse_text(stream.read(), name)


@dataclass
class Run:
    status: int
    stderr: list      # lines
    files: dict       # file name -> text of every file in the output directory


def run_generator(path: str, name: str, out_dir: str) -> Run:
    """Runs the command line in-process."""
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        status = costa_odgen.main(["--eds", path, "--name", name, "--out-dir", out_dir])
    files = {}
    if os.path.isdir(out_dir):
        for file_name in sorted(os.listdir(out_dir)):
            with open(os.path.join(out_dir, file_name), encoding="utf-8") as stream:
                files[file_name] = stream.read()
    return Run(status, err.getvalue().splitlines(), files)


def run_text(text: str, name: str = "test") -> Run:
    """Writes `text` to test.eds in a fresh directory and runs the generator on it."""
    with tempfile.TemporaryDirectory() as directory:
        path = os.path.join(directory, "test.eds")
        with open(path, "w", encoding="utf-8") as stream:
            stream.write(text)
        return run_generator(path, name, os.path.join(directory, "out"))


def generate_example(name: str = "example") -> dict:
    with tempfile.TemporaryDirectory() as directory:
        result = run_generator(EXAMPLE_EDS, name, os.path.join(directory, "out"))
    if result.status != 0:
        raise AssertionError("\n".join(result.stderr))
    return result.files


# A valid device the error tests start from.
BASE = eds("""
    [DeviceInfo]
    ProductName=Base

    [1000]
    ParameterName=Device type
    DataType=0x0007
    AccessType=const
    DefaultValue=0
    """)
