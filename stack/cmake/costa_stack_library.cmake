# The stack library and its optional services (compile-out switches).
#
# Options, chosen at configure time, every one ON by default:
#   COSTA_FEATURE_SDO_BLOCK            SDO block upload and download
#   COSTA_FEATURE_LSS                  LSS slave (CiA 305)
#   COSTA_FEATURE_NODE_GUARDING        node guarding and life guarding (0x100C, 0x100D)
#   COSTA_FEATURE_HEARTBEAT_CONSUMER   heartbeat consumer (0x1016)
#   COSTA_FEATURE_PARAMETER_STORAGE    0x1010/0x1011, stored groups, stored LSS configuration
#   COSTA_FEATURE_TIME                 TIME consumer and producer (0x1012)
#   COSTA_FEATURE_EMCY_CONSUMER        EMCY consumer (0x1028)
#   COSTA_FEATURE_SDO_SERVERS          additional SDO servers (0x1201..0x127F)
#   COSTA_FEATURE_SAFETY               GFC and SRDOs of CiA 304 (0x1300..0x13FF)
#   COSTA_FEATURE_INDICATORS           CiA 303-3 RUN and ERROR LED states (costa::Indicators)
#   COSTA_FEATURE_QUIRK_PROFILES       device profiles other than CiA 301 (NodeSettings::profile)
#
# costa_add_stack_library(<target> [FEATURES <feature>...])
#   A static library of the stack with exactly the listed features (names without the
#   COSTA_FEATURE_ prefix) compiled in. The sources of the others are left out, so nothing can
#   call them by accident: the link would fail. Its PUBLIC include directory holds the
#   generated costa/features.hpp of that set.
#
# costa_missing_features(<out-var> <feature>...)
#   The features of the list that this build tree has switched off (with the prefix).
#
# costa_device_requires(<library> <feature>...)
#   A device library that cannot work without these features: when one is off, the library
#   (and every firmware image of it, see targets/firmware) is left out of `all`, and building it
#   anyway stops at the device's static_assert.
include_guard(GLOBAL)

set(COSTA_OPTIONAL_FEATURES SDO_BLOCK LSS NODE_GUARDING HEARTBEAT_CONSUMER PARAMETER_STORAGE TIME
  EMCY_CONSUMER SDO_SERVERS SAFETY INDICATORS QUIRK_PROFILES)

option(COSTA_FEATURE_SDO_BLOCK "SDO block upload and download (CiA 301)" ON)
option(COSTA_FEATURE_LSS "LSS slave (CiA 305)" ON)
option(COSTA_FEATURE_NODE_GUARDING "Node guarding and life guarding (CiA 301)" ON)
option(COSTA_FEATURE_HEARTBEAT_CONSUMER "Heartbeat consumer, object 0x1016 (CiA 301)" ON)
option(COSTA_FEATURE_PARAMETER_STORAGE "Parameter storage, objects 0x1010/0x1011 (CiA 301)" ON)
option(COSTA_FEATURE_TIME "TIME consumer and producer, object 0x1012 (CiA 301)" ON)
option(COSTA_FEATURE_EMCY_CONSUMER "EMCY consumer, object 0x1028 (CiA 301)" ON)
option(COSTA_FEATURE_SDO_SERVERS "Additional SDO servers, objects 0x1201..0x127F (CiA 301)" ON)
option(COSTA_FEATURE_SAFETY "GFC and SRDOs, objects 0x1300..0x13FF (CiA 304)" ON)
option(COSTA_FEATURE_INDICATORS "RUN and ERROR LED states (CiA 303-3)" ON)
option(COSTA_FEATURE_QUIRK_PROFILES "Device profiles beside CiA 301 (NodeSettings::profile)" ON)

set(COSTA_ENABLED_FEATURES "")
foreach(feature IN LISTS COSTA_OPTIONAL_FEATURES)
  if(COSTA_FEATURE_${feature})
    list(APPEND COSTA_ENABLED_FEATURES ${feature})
  endif()
endforeach()

get_filename_component(COSTA_STACK_DIR "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)

# Every build of the stack has these.
set(COSTA_STACK_CORE_SOURCES
  cob_ids.cpp
  emcy_producer.cpp
  error_control.cpp
  frame_router.cpp
  heartbeat_producer.cpp
  lss_bridge.cpp
  nmt_slave.cpp
  nmt_state_machine.cpp
  node.cpp
  node_dispatch.cpp
  object_access.cpp
  pdo_channel.cpp
  pdo_engine.cpp
  pdo_map.cpp
  pdo_parameters.cpp
  rpdo_channel.cpp
  sdo_server.cpp
  sdo_server_upload.cpp
  sdo_value_reader.cpp
  sdo_value_writer.cpp
  sync_service.cpp
  tpdo_channel.cpp
  transmit_path.cpp)
# The sources of each optional feature.
set(COSTA_STACK_SDO_BLOCK_SOURCES sdo_block_download.cpp sdo_block_upload.cpp sdo_server_block.cpp)
set(COSTA_STACK_LSS_SOURCES lss_identification.cpp lss_slave.cpp)
set(COSTA_STACK_NODE_GUARDING_SOURCES node_guarding.cpp)
set(COSTA_STACK_HEARTBEAT_CONSUMER_SOURCES heartbeat_consumer.cpp)
set(COSTA_STACK_TIME_SOURCES time_service.cpp)
set(COSTA_STACK_EMCY_CONSUMER_SOURCES emcy_consumer.cpp)
set(COSTA_STACK_SDO_SERVERS_SOURCES sdo_servers.cpp)
set(COSTA_STACK_SAFETY_SOURCES safety_service.cpp srdo_channel.cpp srdo_configuration.cpp)
set(COSTA_STACK_INDICATORS_SOURCES indicators.cpp)
# The quirk profiles have no sources of their own: without them the profile's fields are
# constants (costa/profile_choice.hpp), and the services' code for other values folds away.
set(COSTA_STACK_QUIRK_PROFILES_SOURCES "")
set(COSTA_STACK_PARAMETER_STORAGE_SOURCES
  parameter_store.cpp parameter_store_layout.cpp store_commands.cpp stored_image.cpp
  stored_parameters.cpp)

function(costa_add_stack_library target)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "" "FEATURES")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "costa_add_stack_library: unknown arguments: ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  set(sources ${COSTA_STACK_CORE_SOURCES})
  foreach(feature IN LISTS ARG_FEATURES)
    if(NOT feature IN_LIST COSTA_OPTIONAL_FEATURES)
      message(FATAL_ERROR "costa_add_stack_library(${target}): unknown feature ${feature} "
                          "(known: ${COSTA_OPTIONAL_FEATURES})")
    endif()
  endforeach()
  foreach(feature IN LISTS COSTA_OPTIONAL_FEATURES)
    if(feature IN_LIST ARG_FEATURES)
      set(COSTA_FEATURE_${feature}_VALUE true)
      set(COSTA_FEATURE_${feature}_NUMBER 1)  # for the preprocessor
      list(APPEND sources ${COSTA_STACK_${feature}_SOURCES})
    else()
      set(COSTA_FEATURE_${feature}_VALUE false)
      set(COSTA_FEATURE_${feature}_NUMBER 0)
    endif()
  endforeach()
  list(TRANSFORM sources PREPEND "${COSTA_STACK_DIR}/src/")

  set(generated "${CMAKE_CURRENT_BINARY_DIR}/${target}_features")
  configure_file("${COSTA_STACK_DIR}/cmake/features.hpp.in"
                 "${generated}/costa/features.hpp" @ONLY)

  add_library(${target} STATIC ${sources})
  # Installed (tools/cmake/CostaInstall.cmake), the headers and features.hpp are in one directory.
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${COSTA_STACK_DIR}/include>
                                              $<BUILD_INTERFACE:${generated}>
                                              $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(${target} PUBLIC costa_od costa_port_interface
                        PRIVATE $<BUILD_INTERFACE:costa_freestanding>)
endfunction()

function(costa_missing_features out)
  set(missing "")
  foreach(feature IN LISTS ARGN)
    if(NOT feature IN_LIST COSTA_OPTIONAL_FEATURES)
      message(FATAL_ERROR "costa_missing_features: unknown feature ${feature}")
    endif()
    if(NOT feature IN_LIST COSTA_ENABLED_FEATURES)
      list(APPEND missing COSTA_FEATURE_${feature})
    endif()
  endforeach()
  set(${out} "${missing}" PARENT_SCOPE)
endfunction()

function(costa_device_requires library)
  costa_missing_features(missing ${ARGN})
  set_target_properties(${library} PROPERTIES COSTA_MISSING_FEATURES "${missing}")
  if(missing)
    set_target_properties(${library} PROPERTIES EXCLUDE_FROM_ALL ON)
    list(JOIN missing ", " names)
    message(STATUS "${library} is not built: it needs ${names}")
  endif()
endfunction()
