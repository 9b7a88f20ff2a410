# Compile options shared by every Costa target.
#
# costa_warnings      : the warning set, as errors (all code of the project).
# costa_freestanding  : what the core must compile with (stack/, od/, port interfaces).

add_library(costa_warnings INTERFACE)
target_compile_options(costa_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wcast-align
  -Wold-style-cast -Wnull-dereference -Wdouble-promotion -Wformat=2 -Werror)

add_library(costa_freestanding INTERFACE)
target_compile_options(costa_freestanding INTERFACE
  -ffreestanding -fno-exceptions -fno-threadsafe-statics)
# The sanitizer build keeps RTTI in the core: UBSan's vptr check verifies the dynamic type of
# every polymorphic object that host code calls, and needs the core's type information for that.
# Every other build (host, firmware) proves that the core needs no RTTI.
if(NOT COSTA_SANITIZE)
  target_compile_options(costa_freestanding INTERFACE -fno-rtti)
endif()
target_link_libraries(costa_freestanding INTERFACE costa_warnings)

if(COSTA_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined -fno-sanitize-recover=all)
endif()

# Fuzzing build (tools/fuzz, clang only): every object file carries libFuzzer's coverage and the
# sanitizers; the fuzz executables add -fsanitize=fuzzer (libFuzzer's main). The core has no
# RTTI, so UBSan's vptr check, which needs it, is off.
if(COSTA_FUZZ)
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize=vptr
                      -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
