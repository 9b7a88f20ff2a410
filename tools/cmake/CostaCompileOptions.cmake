# Compile options shared by every Costa target.
#
# costa_warnings      : the warning set, as errors (all code of the project).
# costa_freestanding  : what the core must compile with (stack/, od/, port interfaces).
# Neither is exported (tools/cmake/CostaInstall.cmake): the libraries link them as
# $<BUILD_INTERFACE:...>, options of their own compilation only.

add_library(costa_warnings INTERFACE)
target_compile_options(costa_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wcast-align
  -Wold-style-cast -Wnull-dereference -Wdouble-promotion -Wformat=2)
# Errors in Costa's own build; a project that adds Costa as a subdirectory (another compiler
# version, other warnings) gets them as warnings unless it asks (COSTA_WARNINGS_AS_ERRORS).
if(COSTA_WARNINGS_AS_ERRORS)
  target_compile_options(costa_warnings INTERFACE -Werror)
endif()

add_library(costa_freestanding INTERFACE)
target_compile_options(costa_freestanding INTERFACE
  -ffreestanding -fno-exceptions -fno-threadsafe-statics)
# The core calls its ports and hooks through interfaces whose default bodies (no pure virtual
# functions) are never the ones called; an optimising GCC would guess them at every call (a
# compare and a branch before the call). Debug builds do not guess, and clang (clang-tidy
# reads the Debug tree's compile commands) has no such option.
target_compile_options(costa_freestanding INTERFACE
  $<$<AND:$<CXX_COMPILER_ID:GNU>,$<NOT:$<CONFIG:Debug>>>:-fno-devirtualize-speculatively>)
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
# RTTI, so UBSan's vptr check, which needs it, is off. COSTA_FUZZ_FAST (tools/fuzz --fast) keeps
# libFuzzer's coverage without its tracing of comparisons (whose callbacks at every comparison of
# the dictionary's searches cost more than the rest of the instrumentation), without its tracing
# of indirect calls (which feeds only the value profile, which fast runs leave off, and costs a
# division at every virtual call) and without sanitizers. The coverage symbols then come from
# libFuzzer alone: only the fuzz executables (-fsanitize=fuzzer) link in such a tree.
if(COSTA_FUZZ AND COSTA_FUZZ_FAST)
  add_compile_options(-fsanitize=fuzzer-no-link -fno-sanitize-coverage=trace-cmp,indirect-calls)
elseif(COSTA_FUZZ)
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize=vptr
                      -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
