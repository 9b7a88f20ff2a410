# The device targets: the one CMake list of devices (the C++ list is targets/devices.hpp, with
# the same names in the same order; the test device_lists compares them and every consumer).
#
#   costa_device(NAME DIRECTORY)
#
# NAME is the device's name everywhere (costa-slave DEVICE, a transcript's `device` line, the
# images costa-NAME-firmware, the fuzzer costa_fuzz_NAME): lower case, a C++ identifier.
# DIRECTORY is below targets/ and defines the library costa_device_NAME (costa_add_device()).
# The build, tools/fuzz and tools/footprint (through tools/devices) read this file.
costa_device(example example)
costa_device(solo solo)
costa_device(gra gefran)
costa_device(grn gefran)
costa_device(santeng santeng)
costa_device(mseries mseries)
