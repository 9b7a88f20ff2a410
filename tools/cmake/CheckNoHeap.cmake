# Fails when a linked firmware image contains heap or C++-runtime symbols.
#   cmake -DNM=arm-none-eabi-nm -DELF=image.elf -P CheckNoHeap.cmake
execute_process(COMMAND "${NM}" "${ELF}" OUTPUT_VARIABLE symbols RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cannot list the symbols of ${ELF}")
endif()
string(REPLACE "\n" ";" lines "${symbols}")
set(forbidden "")
foreach(line IN LISTS lines)
  # "<address> <type> <name>" or "         U <name>"
  if(line MATCHES " [A-Za-z] ([^ ]+)$")
    set(name "${CMAKE_MATCH_1}")
    if(name MATCHES "^_?(malloc|free|calloc|realloc|_malloc_r|_free_r|_calloc_r|_realloc_r)$"
       OR name MATCHES "^_Zn[wa]"          # operator new, new[]
       OR name MATCHES "^_Zd[la]"          # operator delete, delete[]
       OR name MATCHES "^__cxa_"           # C++ runtime (exceptions, guards, pure virtual)
       OR name MATCHES "^__gxx_personality")
      list(APPEND forbidden "${name}")
    endif()
  endif()
endforeach()
get_filename_component(image "${ELF}" NAME)
if(forbidden)
  list(REMOVE_DUPLICATES forbidden)
  message(FATAL_ERROR "${image} references forbidden symbols: ${forbidden}")
endif()
message(STATUS "no-heap check passed: ${image} has no malloc/free, operator new/delete, __cxa_* or __gxx_personality* symbols")
