# Toolchain for the firmware build: arm-none-eabi-g++ (Debian gcc-arm-none-eabi), newlib-nano.
#   cmake -S . -B build-m4 -DCMAKE_TOOLCHAIN_FILE=tools/cmake/arm-none-eabi.cmake \
#         -DCOSTA_ARM_CPU=cortex-m4 -DCMAKE_BUILD_TYPE=MinSizeRel
# COSTA_ARM_CPU: cortex-m4 (default, single-precision FPU) or cortex-m0plus.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
set(CMAKE_OBJCOPY arm-none-eabi-objcopy)
set(CMAKE_SIZE arm-none-eabi-size)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

if(NOT COSTA_ARM_CPU)
  set(COSTA_ARM_CPU cortex-m4)
endif()
set(COSTA_ARM_CPU "${COSTA_ARM_CPU}" CACHE STRING "Cortex-M core of the firmware build")

if(COSTA_ARM_CPU STREQUAL "cortex-m4")
  set(cpu_flags "-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16")
elseif(COSTA_ARM_CPU STREQUAL "cortex-m0plus")
  set(cpu_flags "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft")
else()
  message(FATAL_ERROR "COSTA_ARM_CPU must be cortex-m4 or cortex-m0plus")
endif()

set(common_flags "${cpu_flags} -ffunction-sections -fdata-sections")
set(CMAKE_C_FLAGS_INIT "${common_flags}")
set(CMAKE_CXX_FLAGS_INIT "${common_flags} -fno-exceptions -fno-rtti -fno-threadsafe-statics -fno-use-cxa-atexit")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${cpu_flags} --specs=nano.specs -nostartfiles -Wl,--gc-sections")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
