# The device list (targets/devices.cmake) and what a device directory declares.
#
# costa_device(<name> <directory>)
#   One line of targets/devices.cmake: appends <name> to COSTA_DEVICE_NAMES and its directory
#   below targets/ to COSTA_DEVICE_DIRECTORIES (each directory once).
#
# costa_add_device(<name> LIBRARIES <library>... DICTIONARY <od-library>)
#   Called by the device's directory: defines costa_device_<name>, what a program links to run
#   the device (its composition, behaviour and dictionary, and the dictionary's entry names,
#   which only host programs use). The device's features come from costa_device_requires() on
#   its libraries (call it first): costa_device_<name> carries their COSTA_MISSING_FEATURES.
#   The headers of every device are also given to costa_device_headers (include directories,
#   generated dictionary headers), so that targets/devices.hpp compiles in a program that links
#   only one device: a firmware image.
include_guard(GLOBAL)

set(COSTA_DEVICE_NAMES "")
set(COSTA_DEVICE_DIRECTORIES "")

macro(costa_device name directory)
  if(NOT "${name}" MATCHES "^[a-z][a-z0-9_]*$")
    message(FATAL_ERROR "targets/devices.cmake: device name '${name}' is not a lower-case C++ "
                        "identifier")
  endif()
  if("${name}" IN_LIST COSTA_DEVICE_NAMES)
    message(FATAL_ERROR "targets/devices.cmake: device '${name}' is listed twice")
  endif()
  list(APPEND COSTA_DEVICE_NAMES ${name})
  if(NOT "${directory}" IN_LIST COSTA_DEVICE_DIRECTORIES)
    list(APPEND COSTA_DEVICE_DIRECTORIES ${directory})
  endif()
endmacro()

function(costa_add_device name)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "DICTIONARY" "LIBRARIES")
  if(ARG_UNPARSED_ARGUMENTS OR NOT ARG_DICTIONARY OR NOT ARG_LIBRARIES)
    message(FATAL_ERROR "usage: costa_add_device(<name> LIBRARIES <library>... "
                        "DICTIONARY <od-library>)")
  endif()
  if(NOT "${name}" IN_LIST COSTA_DEVICE_NAMES)
    message(FATAL_ERROR "costa_add_device(${name}): '${name}' is not in targets/devices.cmake")
  endif()
  set(device costa_device_${name})
  add_library(${device} INTERFACE)
  target_link_libraries(${device} INTERFACE ${ARG_LIBRARIES} ${ARG_DICTIONARY}
                        ${ARG_DICTIONARY}_names costa_device_common)
  set(missing "")
  foreach(library IN LISTS ARG_LIBRARIES)
    get_target_property(library_missing ${library} COSTA_MISSING_FEATURES)
    if(library_missing)
      list(APPEND missing ${library_missing})
    endif()
  endforeach()
  list(REMOVE_DUPLICATES missing)
  set_target_properties(${device} PROPERTIES COSTA_MISSING_FEATURES "${missing}"
                                             COSTA_DICTIONARY ${ARG_DICTIONARY})
  foreach(library IN LISTS ARG_LIBRARIES)
    target_include_directories(costa_device_headers INTERFACE
                               $<TARGET_PROPERTY:${library},INTERFACE_INCLUDE_DIRECTORIES>)
  endforeach()
  # Linking the dictionary orders its header generation before any compile of a program that
  # includes the device's headers.
  target_link_libraries(costa_device_headers INTERFACE ${ARG_DICTIONARY})
endfunction()
