# cmake -DINPUT=FILE -DOUTPUT=FILE.cpp -DFUNCTION=NAME -P EmbedFile.cmake
#
# Writes a C++ source defining `std::string_view costa::host::NAME()`: the bytes of INPUT,
# unchanged (line ends, trailing spaces and all), for host programs that hand a file out as it
# is (costa-slave --eds). The text is an array, not a string literal, so that no byte of the
# file needs escaping and a NUL in it would not end it.
foreach(variable INPUT OUTPUT FUNCTION)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "EmbedFile.cmake: -D${variable}=... is required")
  endif()
endforeach()

file(READ "${INPUT}" hex HEX)
string(LENGTH "${hex}" digits)
math(EXPR size "${digits} / 2")
# 0x.., per byte, 16 to a line.
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
string(REGEX REPLACE "((0x[0-9a-f][0-9a-f],){16})" "\\1\n    " bytes "${bytes}")
get_filename_component(name "${INPUT}" NAME)

file(WRITE "${OUTPUT}.tmp" "// Generated from ${name} by tools/cmake/EmbedFile.cmake: do not edit.
#include <string_view>

namespace costa::host {
namespace {
constexpr unsigned char kBytes[${size} + 1] = {
    ${bytes}0};
}  // namespace

std::string_view ${FUNCTION}();
std::string_view ${FUNCTION}() {
  // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): the file's bytes as text
  return {reinterpret_cast<const char*>(kBytes), ${size}};
}

}  // namespace costa::host
")
# Rewritten only when it changed, so that an unchanged file compiles once.
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
