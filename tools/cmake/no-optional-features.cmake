# Initial cache of a firmware tree with every optional feature compiled out (cmake -C): the ten
# services and the quirk profiles (stack/cmake/costa_stack_library.cmake). tools/run-tests builds
# such a tree, build-cortex-m0plus-no-options/, and tools/check-budgets measures it.
foreach(feature SDO_BLOCK LSS NODE_GUARDING HEARTBEAT_CONSUMER PARAMETER_STORAGE TIME
        EMCY_CONSUMER SDO_SERVERS SAFETY INDICATORS QUIRK_PROFILES)
  set(COSTA_FEATURE_${feature} OFF CACHE BOOL "" FORCE)
endforeach()
