# cmake -DREADELF=<arm-none-eabi-readelf> -DIMAGE=<elf> -P check_image.cmake
# An image for Linux's remoteproc on the STM32MP15: it has a .resource_table section, its vector table is at 0, every
# section it loads lies in RETRAM (0x00000000, 64 KB) or in the MCU SRAM below the RPMsg regions (0x10000000 to
# 0x10040000: the vrings and buffers that follow belong to Linux), and code + data fit 256 KB. Prints the sizes.
execute_process(COMMAND ${READELF} --section-headers --wide ${IMAGE}
                RESULT_VARIABLE exit_code OUTPUT_VARIABLE sections ERROR_VARIABLE err)
if(NOT exit_code EQUAL 0)
  message(FATAL_ERROR "${READELF} failed on ${IMAGE}: ${err}")
endif()
if(NOT sections MATCHES "\\.resource_table +PROGBITS")
  message(FATAL_ERROR "${IMAGE} has no .resource_table section: remoteproc would refuse it")
endif()
if(NOT sections MATCHES "\\.vector_table +PROGBITS +00000000 ")
  message(FATAL_ERROR "${IMAGE}'s vector table is not at address 0")
endif()

set(text 0)
set(data 0)
string(REPLACE "\n" ";" lines "${sections}")
foreach(line IN LISTS lines)
  # [Nr] Name Type Address Off Size ES Flg ...
  if(NOT line MATCHES "^ *\\[ *[0-9]+\\] +([^ ]+) +([A-Z_]+) +([0-9a-f]+) +[0-9a-f]+ +([0-9a-f]+) +[0-9a-f]+ +([A-Z]*)")
    continue()
  endif()
  set(name "${CMAKE_MATCH_1}")
  set(type "${CMAKE_MATCH_2}")
  set(flags "${CMAKE_MATCH_5}")
  math(EXPR address "0x${CMAKE_MATCH_3}")
  math(EXPR size "0x${CMAKE_MATCH_4}")
  if(NOT flags MATCHES "A" OR size EQUAL 0)
    continue()  # not loaded into the core's memory
  endif()
  math(EXPR end "${address} + ${size}")
  if(NOT ((address GREATER_EQUAL 0 AND end LESS_EQUAL 65536) OR
          (address GREATER_EQUAL 268435456 AND end LESS_EQUAL 268697600)))  # 0x10000000 .. 0x10040000
    math(EXPR shown_end "${end}" OUTPUT_FORMAT HEXADECIMAL)
    message(FATAL_ERROR "${IMAGE}: section ${name} ends at ${shown_end}, outside RETRAM and the M4's MCU SRAM")
  endif()
  if(type STREQUAL "NOBITS" OR flags MATCHES "W")
    math(EXPR data "${data} + ${size}")
  else()
    math(EXPR text "${text} + ${size}")
  endif()
endforeach()
math(EXPR total "${text} + ${data}")
message(STATUS "${IMAGE}: code and constants ${text} B, data, zeroed data and stack ${data} B, ${total} B in all")
if(total GREATER 262144)
  message(FATAL_ERROR "${IMAGE}: ${total} B is more than the 256 KB of MCU SRAM the image may use")
endif()
