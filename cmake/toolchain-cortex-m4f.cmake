# Cortex-M4 with single-precision FPU (STM32MP15's real-time core; QEMU's mps2-an386), bare metal, gcc-arm-none-eabi.
# Firmware is freestanding: no exceptions, no RTTI, no C library and no heap. It links libgcc only, so any use of
# malloc, operator new or printf is an undefined reference at link time rather than a surprise at run time.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(DUET_CORTEX_M4F_FLAGS "-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16")
# -fcallgraph-info=su: each object's stack usage and calls beside it (.ci), for the worst-case stack of each image
# (ports/cortex-m/worst_case_stack.py).
set(CMAKE_C_FLAGS_INIT "${DUET_CORTEX_M4F_FLAGS} -ffunction-sections -fdata-sections -fcallgraph-info=su")
set(CMAKE_CXX_FLAGS_INIT
    "${DUET_CORTEX_M4F_FLAGS} -ffunction-sections -fdata-sections -fcallgraph-info=su -fno-exceptions -fno-rtti -fno-threadsafe-statics -fno-use-cxa-atexit")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-nostdlib -Wl,--gc-sections -Wl,--print-memory-usage")
# libgcc last on every link line, after every library a firmware links (its soft-float and 64-bit helpers).
set(CMAKE_C_STANDARD_LIBRARIES "-lgcc")
set(CMAKE_CXX_STANDARD_LIBRARIES "-lgcc")

foreach(tool objcopy objdump size readelf nm)
  string(TOUPPER "${tool}" variable)
  find_program(DUET_ARM_NONE_EABI_${variable} arm-none-eabi-${tool} REQUIRED)
endforeach()

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
