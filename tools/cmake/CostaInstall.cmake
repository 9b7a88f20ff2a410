# The install rules and the CMake package `Costa` (docs/cmake-package.md):
#
#   cmake --install <build> --prefix <prefix>
#   find_package(Costa CONFIG REQUIRED)       # CMAKE_PREFIX_PATH=<prefix>
#
# Installs the libraries this tree builds as namespaced targets (Costa::od, Costa::stack,
# Costa::cia402, Costa::port_interface, and Costa::port_linux on a host, Costa::port_stm32 where
# the bxCAN port is built), their headers, the stack's costa/features.hpp (the services compiled
# in), the EDS generator (Python) and costa_add_object_dictionary(), and a version file. Every
# path in the package is relative to its prefix: nothing points back into the source or build
# tree (tools/check-integration checks it).
include_guard(GLOBAL)
include(CMakePackageConfigHelpers)

set(COSTA_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/Costa")
set(COSTA_INSTALL_GENERATORDIR "${CMAKE_INSTALL_DATADIR}/costa/generator")

set(exported costa_od costa_stack costa_cia402 costa_port_interface)
set(header_directories
    "${PROJECT_SOURCE_DIR}/od/include/"
    "${PROJECT_SOURCE_DIR}/stack/include/"
    "${PROJECT_SOURCE_DIR}/stack/cia402/include/"
    "${PROJECT_SOURCE_DIR}/port/include/")
if(TARGET costa_port_linux)
  list(APPEND exported costa_port_linux)
  list(APPEND header_directories "${PROJECT_SOURCE_DIR}/port/linux/include/")
endif()
if(TARGET costa_port_stm32)
  list(APPEND exported costa_port_stm32)
  list(APPEND header_directories "${PROJECT_SOURCE_DIR}/port/stm32/include/")
endif()

install(TARGETS ${exported} EXPORT CostaTargets
        ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(DIRECTORY ${header_directories} DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}"
        FILES_MATCHING PATTERN "*.hpp")
# The services costa_stack was built with (stack/cmake/costa_stack_library.cmake).
install(FILES "${PROJECT_BINARY_DIR}/stack/costa_stack_features/costa/features.hpp"
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/costa")

get_property(generator_dir GLOBAL PROPERTY COSTA_ODGEN_DIR)
get_property(generator_modules GLOBAL PROPERTY COSTA_ODGEN_SOURCES)
list(TRANSFORM generator_modules PREPEND "${generator_dir}/")
install(FILES ${generator_modules} DESTINATION "${COSTA_INSTALL_GENERATORDIR}")
install(FILES "${PROJECT_SOURCE_DIR}/od/cmake/costa_object_dictionary.cmake"
        DESTINATION "${COSTA_INSTALL_CMAKEDIR}")

install(EXPORT CostaTargets NAMESPACE Costa:: DESTINATION "${COSTA_INSTALL_CMAKEDIR}")

set(COSTA_PACKAGE_FEATURES ${COSTA_ENABLED_FEATURES})
configure_package_config_file("${CMAKE_CURRENT_LIST_DIR}/CostaConfig.cmake.in"
                              "${PROJECT_BINARY_DIR}/CostaConfig.cmake"
                              INSTALL_DESTINATION "${COSTA_INSTALL_CMAKEDIR}"
                              PATH_VARS COSTA_INSTALL_GENERATORDIR)
# A 0.x release is compatible only with the same minor version.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/CostaConfigVersion.cmake"
                                 VERSION "${PROJECT_VERSION}" COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/CostaConfig.cmake"
              "${PROJECT_BINARY_DIR}/CostaConfigVersion.cmake"
        DESTINATION "${COSTA_INSTALL_CMAKEDIR}")
