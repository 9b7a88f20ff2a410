"""The CMake integration: its list of generator modules, and a throwaway project that uses
costa_add_object_dictionary()."""

import glob
import os
import re
import shutil
import subprocess
import tempfile
import unittest

from tests.helpers import EXAMPLE_EDS, GENERATOR_DIR, INCLUDE_DIR, REPO_ROOT

CMAKE_MODULE = os.path.join(REPO_ROOT, "od", "cmake", "costa_object_dictionary.cmake")
# The limit check the example's definition names and what it calls (od/src, part of costa_od).
LIMIT_CHECKS = " ".join('"' + os.path.join(REPO_ROOT, "od", "src", name) + '"'
                        for name in ("limit_checks.cpp", "little_endian.cpp"))

PROJECT = """
cmake_minimum_required(VERSION 3.20)
project(odgen_cmake_test CXX)
set(CMAKE_CXX_STANDARD 17)
include("{module}")
add_library(costa_od STATIC {limit_checks})
target_include_directories(costa_od PUBLIC "{include}")
costa_add_object_dictionary(device_od EDS example.eds NAME example)
add_executable(app main.cpp)
target_link_libraries(app PRIVATE device_od_names)
"""

MAIN = """
#include "example_od.hpp"
int main() {
  return costa::gen::example::kDefinition.objectCount == 31 &&
                 costa::gen::example::kNames.count > 0 ? 0 : 1;
}
"""


class CMakeTest(unittest.TestCase):
    def test_module_list_names_every_generator_module(self):
        with open(CMAKE_MODULE, encoding="utf-8") as stream:
            text = stream.read()
        listed = re.search(r"COSTA_ODGEN_SOURCES\n(.*?)\)", text, re.DOTALL).group(1).split()
        present = sorted(os.path.basename(p) for p in glob.glob(os.path.join(GENERATOR_DIR,
                                                                           "*.py")))
        self.assertEqual(sorted(listed), present)

    def test_project_builds(self):
        cmake = shutil.which("cmake")
        if cmake is None or shutil.which("c++") is None:
            self.skipTest("cmake or c++ not found")
        with tempfile.TemporaryDirectory() as source:
            with open(os.path.join(source, "CMakeLists.txt"), "w", encoding="utf-8") as stream:
                stream.write(PROJECT.format(module=CMAKE_MODULE, include=INCLUDE_DIR, limit_checks=LIMIT_CHECKS))
            with open(os.path.join(source, "main.cpp"), "w", encoding="utf-8") as stream:
                stream.write(MAIN)
            shutil.copy(EXAMPLE_EDS, os.path.join(source, "example.eds"))
            build = os.path.join(source, "build")
            self._run([cmake, "-S", source, "-B", build])
            first = self._run([cmake, "--build", build])
            self.assertIn("Generating object dictionary example from example.eds", first)
            for name in ("example_od.hpp", "example_od.cpp", "example_od_names.cpp"):
                self.assertTrue(os.path.isfile(os.path.join(build, "gen", "example", name)))
            self._run([os.path.join(build, "app")])
            second = self._run([cmake, "--build", build])
            self.assertNotIn("Generating object dictionary", second)

    def test_an_eds_error_fails_the_build_with_file_and_line(self):
        cmake = shutil.which("cmake")
        if cmake is None or shutil.which("c++") is None:
            self.skipTest("cmake or c++ not found")
        with open(EXAMPLE_EDS, encoding="utf-8") as stream:
            lines = stream.read().split("\n")
        # The first DataType line of the EDS names a type that does not exist.
        bad = next(i for i, line in enumerate(lines) if line.startswith("DataType="))
        lines[bad] = "DataType=0x0099"
        with tempfile.TemporaryDirectory() as source:
            with open(os.path.join(source, "CMakeLists.txt"), "w", encoding="utf-8") as stream:
                stream.write(PROJECT.format(module=CMAKE_MODULE, include=INCLUDE_DIR, limit_checks=LIMIT_CHECKS))
            with open(os.path.join(source, "main.cpp"), "w", encoding="utf-8") as stream:
                stream.write(MAIN)
            with open(os.path.join(source, "example.eds"), "w", encoding="utf-8") as stream:
                stream.write("\n".join(lines))
            build = os.path.join(source, "build")
            self._run([cmake, "-S", source, "-B", build])
            done = subprocess.run([cmake, "--build", build], capture_output=True, text=True)
            self.assertNotEqual(done.returncode, 0, done.stdout + done.stderr)
            self.assertIn(f"example.eds:{bad + 1}", done.stdout + done.stderr)
            self.assertFalse(os.path.exists(os.path.join(build, "app")))

    def _run(self, command):
        done = subprocess.run(command, capture_output=True, text=True)
        self.assertEqual(done.returncode, 0, f"{' '.join(command)}\n{done.stdout}{done.stderr}")
        return done.stdout


if __name__ == "__main__":
    unittest.main()
