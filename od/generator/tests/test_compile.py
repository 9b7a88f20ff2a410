"""Compiles the generated code of the rich fixture with the project's warning flags, then links
it into a small host program that walks kDefinition and prints every value the tables point
at; the printout must match the model byte for byte (this proves the offsets and the order of
the initializers)."""

import os
import shutil
import struct
import subprocess
import tempfile
import unittest

from tests.helpers import EXAMPLE_EDS, INCLUDE_DIR, REPO_ROOT, parse_file, run_generator

STRICT_FLAGS = ["-std=c++17", "-Wall", "-Wextra", "-Wpedantic", "-Wconversion", "-Wshadow",
                "-Wcast-align", "-Wold-style-cast", "-Wnull-dereference", "-Wdouble-promotion",
                "-Wformat=2",
                "-Wmissing-field-initializers", "-Werror", "-ffreestanding", "-fno-exceptions",
                "-fno-rtti", "-fno-threadsafe-statics"]

CHECKER = r"""
#include <stdio.h>
#include "costa/od/object_dictionary.hpp"
#include "example_od.hpp"

namespace gen = costa::gen::example;

int main() {
  const costa::od::Definition& d = gen::kDefinition;
  printf("D %s %u\n", d.deviceName, static_cast<unsigned>(d.objectCount));
  printf("C %u %u %u %u %u %u\n", unsigned{gen::Capacity::kRpdoCount},
         unsigned{gen::Capacity::kTpdoCount}, unsigned{gen::Capacity::kLargestValue},
         unsigned{gen::Capacity::kHeartbeatConsumers}, unsigned{gen::Capacity::kErrorHistory},
         unsigned{gen::Capacity::kObjectCount});
  for (uint16_t o = 0; o < d.objectCount; ++o) {
    const costa::od::Object& object = d.objects[o];
    for (uint8_t r = 0; r < object.rowCount; ++r) {
      const costa::od::SubEntry& e = costa::od::rowsOf(d, object)[r];
      for (unsigned k = 0; k < e.count; ++k) {
        const bool rom = (e.attributes & costa::od::kInRom) != 0;
        const costa::od::EntryRef ref =
            costa::od::EntryRef::at(object, e, static_cast<uint8_t>(e.subIndex + k));
        unsigned char defaults[300] = {};
        if (!rom && e.type != costa::od::DataType::kDomain) {
          costa::od::copyDefault(d, ref, defaults);
        }
        const unsigned char* block = rom ? static_cast<const unsigned char*>(d.constants)
                                         : defaults;
        const unsigned offset = rom ? ref.offset() : 0;
        printf("E %04X %u %04X %u %u %u %u ", unsigned{object.index}, e.subIndex + k,
               static_cast<unsigned>(e.type), unsigned{e.attributes}, unsigned{e.size},
               unsigned{e.group}, static_cast<unsigned>(object.code));
        for (unsigned i = 0; i < e.size; ++i) printf("%02X", unsigned{block[offset + i]});
        if (e.limits != 0) {
          const costa::od::Limits& limits = d.limits[e.limits - 1];
          printf(" L%016llX:%016llX", static_cast<unsigned long long>(limits.low),
                 static_cast<unsigned long long>(limits.high));
        }
        printf("\n");
      }
    }
  }
  for (uint32_t i = 0; i < gen::kNames.count; ++i) {
    const costa::od::EntryName& n = gen::kNames.names[i];
    printf("N %04X %u %s\n", unsigned{n.index}, unsigned{n.subIndex}, n.name);
  }
  return 0;
}
"""


def _value_bytes(entry) -> bytes:
    kind, size = entry.data_type.kind, entry.size
    if kind == "domain":
        return b""
    if kind in ("visible", "octet"):
        return entry.default + bytes(size - len(entry.default))
    if kind == "real":
        return struct.pack("<f" if size == 4 else "<d", entry.default)
    return (entry.default & ((1 << (8 * size)) - 1)).to_bytes(size, "little")


def _pattern(value, data_type) -> int:
    if data_type.kind == "real":
        return struct.unpack("<Q", struct.pack("<d", value))[0]
    return value & ((1 << 64) - 1)


def expected_lines(device) -> list:
    lines = [f"D {device.product_name} {len(device.objects)}"]
    for obj in device.objects:
        for e in obj.entries:
            line = (f"E {e.index:04X} {e.sub} {e.data_type.code:04X} {e.attributes} {e.size} "
                    f"{e.group} {obj.code} {_value_bytes(e).hex().upper()}")
            if e.has_limits:
                line += (f" L{_pattern(e.low, e.data_type):016X}:"
                         f"{_pattern(e.high, e.data_type):016X}")
            lines.append(line)
    for obj in device.objects:
        for e in obj.entries:
            lines.append(f"N {e.index:04X} {e.sub} {obj.full_name(e)}")
    return lines


def compilers() -> list:
    found = []
    for names in (("g++",), ("clang++-14", "clang++")):
        for name in names:
            path = shutil.which(name)
            if path:
                found.append(path)
                break
    return found


class CompileTest(unittest.TestCase):
    def test_generated_code_compiles_and_matches_the_model(self):
        available = compilers()
        if not any(os.path.basename(c) == "g++" for c in available):
            self.skipTest("g++ not found: the generated code was not compiled")
        device, _ = parse_file(EXAMPLE_EDS, "example")
        expected = expected_lines(device)
        with tempfile.TemporaryDirectory() as work:
            out = os.path.join(work, "gen")
            self.assertEqual(run_generator(EXAMPLE_EDS, "example", out).status, 0)
            checker = os.path.join(work, "checker.cpp")
            with open(checker, "w", encoding="utf-8") as stream:
                stream.write(CHECKER)
            for compiler in available:
                with self.subTest(compiler=os.path.basename(compiler)):
                    objects = []
                    # The limit check the example's definition names and the defaults'
                    # reader live in od/src.
                    sources = [os.path.join(out, "example_od.cpp"),
                               os.path.join(out, "example_od_names.cpp"),
                               *(os.path.join(REPO_ROOT, "od", "src", name)
                                 for name in ("limit_checks.cpp", "object_dictionary.cpp",
                                              "dictionary_defaults.cpp", "little_endian.cpp"))]
                    for source in sources:
                        name = os.path.basename(source)
                        obj = os.path.join(work, f"{os.path.basename(compiler)}-{name}.o")
                        self._run([compiler, *STRICT_FLAGS, "-I", INCLUDE_DIR, "-I", out, "-c",
                                   source, "-o", obj])
                        objects.append(obj)
                    program = os.path.join(work, f"{os.path.basename(compiler)}-checker")
                    self._run([compiler, "-std=c++17", "-Wall", "-Wextra", "-Werror", "-I",
                               INCLUDE_DIR, "-I", out, checker, *objects, "-o", program])
                    printed = subprocess.run([program], capture_output=True, text=True,
                                             check=True).stdout.splitlines()
                    self.assertEqual(printed[0], expected[0])
                    self.assertEqual(printed[1], "C 2 1 20 3 4 31")
                    self.assertEqual(printed[2:], expected[1:])

    def _run(self, command):
        done = subprocess.run(command, capture_output=True, text=True)
        self.assertEqual(done.returncode, 0, f"{' '.join(command)}\n{done.stderr}")
        self.assertEqual(done.stderr, "", "the compiler printed diagnostics")


if __name__ == "__main__":
    unittest.main()
