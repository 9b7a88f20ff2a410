#!/usr/bin/env python3
"""costa_odgen: generates the C++ object dictionary tables of Costa from an EDS (CiA 306).

    python3 costa_odgen.py --eds FILE.eds --name NAME --out-dir DIR

writes DIR/NAME_od.hpp, DIR/NAME_od.cpp and DIR/NAME_od_names.cpp. Files whose content would
not change are left untouched. Problems in the EDS are printed as `FILE:LINE: error: ...`;
when there is any error, nothing is written and the exit status is 1.
"""

import sys

sys.dont_write_bytecode = True  # keep the source tree free of __pycache__ when run by builds

import argparse  # noqa: E402
import os  # noqa: E402

from cpp_emitter import emit  # noqa: E402
from cpp_names import is_identifier  # noqa: E402
from diagnostics import Diagnostics  # noqa: E402
from eds_parser import parse_eds  # noqa: E402
from ini_reader import decode_text, read_ini  # noqa: E402


def generate(eds_path: str, name: str, diag: Diagnostics):
    """Parses the EDS; returns {file name: text}, or None when `diag` holds errors."""
    with open(eds_path, "rb") as stream:
        text = decode_text(stream.read())
    ini = read_ini(text, diag)
    device = parse_eds(ini, diag, name)
    if diag.has_errors:
        return None
    return emit(device, name, os.path.basename(eds_path))


def write_if_changed(path: str, text: str) -> bool:
    """Writes `text` unless the file already holds it; True when the file was written."""
    data = text.encode("utf-8")
    try:
        with open(path, "rb") as stream:
            if stream.read() == data:
                return False
    except FileNotFoundError:
        pass
    temporary = path + ".tmp"
    with open(temporary, "wb") as stream:
        stream.write(data)
    os.replace(temporary, path)
    return True


def _arguments(argv):
    parser = argparse.ArgumentParser(
        prog="costa_odgen", description="Generate Costa object dictionary tables from an EDS.")
    parser.add_argument("--eds", required=True, help="the EDS file (CiA 306)")
    parser.add_argument("--name", required=True,
                        help="C++ identifier: namespace costa::gen::NAME, files NAME_od.*")
    parser.add_argument("--out-dir", required=True, help="directory for the generated files")
    args = parser.parse_args(argv)
    if not is_identifier(args.name):
        parser.error(f"--name '{args.name}' is not a C++ identifier")
    return args


def main(argv=None) -> int:
    args = _arguments(argv)
    diag = Diagnostics()
    try:
        files = generate(args.eds, args.name, diag)
    except OSError as exc:
        print(f"{args.eds}: error: cannot read: {exc.strerror}", file=sys.stderr)
        return 1
    for line in diag.format(args.eds):
        print(line, file=sys.stderr)
    if files is None:
        return 1
    try:
        os.makedirs(args.out_dir, exist_ok=True)
        for file_name, text in files.items():
            write_if_changed(os.path.join(args.out_dir, file_name), text)
    except OSError as exc:
        print(f"costa_odgen: error: cannot write {exc.filename}: {exc.strerror}",
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
