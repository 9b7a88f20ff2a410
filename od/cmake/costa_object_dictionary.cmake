# costa_add_object_dictionary(<target> EDS <path> NAME <cppname>)
#
# Generates the object dictionary tables of an EDS (CiA 306) at build time and defines two
# static libraries:
#   <target>        NAME_od.cpp: costa::gen::<cppname>::kDefinition and its value blocks.
#                   Its PUBLIC include directory holds <cppname>_od.hpp; links the dictionary
#                   runtime: Costa::od (Costa's tree, or the installed package), else costa_od.
#   <target>_names  NAME_od_names.cpp: costa::gen::<cppname>::kNames (optional for firmware).
# The generated files live in ${CMAKE_CURRENT_BINARY_DIR}/gen/<cppname>/. They are rewritten
# only when their content changes, so editing the EDS recompiles only what it affects.
#
# The generator's directory is od/generator beside this file; the installed package
# (CostaConfig.cmake) sets COSTA_ODGEN_DIR to its copy before including this file.
include_guard(GLOBAL)

if(NOT COSTA_ODGEN_DIR)
  set(COSTA_ODGEN_DIR "${CMAKE_CURRENT_LIST_DIR}/../generator")
endif()
set_property(GLOBAL PROPERTY COSTA_ODGEN_DIR "${COSTA_ODGEN_DIR}")

# Every module of the generator: a change to any of them regenerates the tables.
set_property(GLOBAL PROPERTY COSTA_ODGEN_SOURCES
  costa_odgen.py
  cpp_emitter.py
  cpp_layout.py
  cpp_literals.py
  cpp_names.py
  cpp_rows.py
  data_types.py
  diagnostics.py
  eds_model.py
  eds_parser.py
  entry_parser.py
  ini_reader.py
  object_lists.py
  value_parser.py
)

function(costa_add_object_dictionary target)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "EDS;NAME" "")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "costa_add_object_dictionary: unknown arguments: ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT ARG_EDS OR NOT ARG_NAME)
    message(FATAL_ERROR "costa_add_object_dictionary(${target}): EDS and NAME are required")
  endif()
  if(NOT ARG_NAME MATCHES "^[A-Za-z_][A-Za-z0-9_]*$")
    message(FATAL_ERROR "costa_add_object_dictionary(${target}): NAME '${ARG_NAME}' is not a C++ identifier")
  endif()

  # Python is looked up once per build tree; later calls reuse the interpreter found first.
  get_property(python GLOBAL PROPERTY COSTA_ODGEN_PYTHON)
  if(NOT python)
    find_package(Python3 3.8 REQUIRED COMPONENTS Interpreter)
    set(python "${Python3_EXECUTABLE}")
    set_property(GLOBAL PROPERTY COSTA_ODGEN_PYTHON "${python}")
  endif()

  get_property(generator_dir GLOBAL PROPERTY COSTA_ODGEN_DIR)
  get_filename_component(generator_dir "${generator_dir}" ABSOLUTE)
  get_property(module_names GLOBAL PROPERTY COSTA_ODGEN_SOURCES)
  set(generator_sources "")
  foreach(module IN LISTS module_names)
    list(APPEND generator_sources "${generator_dir}/${module}")
  endforeach()

  get_filename_component(eds "${ARG_EDS}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  set(out_dir "${CMAKE_CURRENT_BINARY_DIR}/gen/${ARG_NAME}")
  set(out_hpp "${out_dir}/${ARG_NAME}_od.hpp")
  set(out_cpp "${out_dir}/${ARG_NAME}_od.cpp")
  set(out_names "${out_dir}/${ARG_NAME}_od_names.cpp")

  add_custom_command(
    OUTPUT "${out_hpp}" "${out_cpp}" "${out_names}"
    COMMAND "${python}" -B "${generator_dir}/costa_odgen.py"
            --eds "${eds}" --name "${ARG_NAME}" --out-dir "${out_dir}"
    DEPENDS "${eds}" ${generator_sources}
    COMMENT "Generating object dictionary ${ARG_NAME} from ${ARG_EDS}"
    VERBATIM)

  add_library(${target} STATIC "${out_cpp}" "${out_hpp}")
  target_include_directories(${target} PUBLIC "${out_dir}")
  if(TARGET Costa::od)
    target_link_libraries(${target} PUBLIC Costa::od)
  else()
    target_link_libraries(${target} PUBLIC costa_od)
  endif()
  # The EDS it was generated from, for programs that hand it out (costa-slave --eds).
  set_target_properties(${target} PROPERTIES COSTA_EDS "${eds}")
  if(TARGET costa_freestanding)
    # Generated tables are part of the freestanding core.
    target_link_libraries(${target} PRIVATE costa_freestanding)
  endif()

  add_library(${target}_names STATIC "${out_names}")
  target_link_libraries(${target}_names PUBLIC ${target})
  if(TARGET costa_freestanding)
    target_link_libraries(${target}_names PRIVATE costa_freestanding)
  endif()
endfunction()
