# cmake -DREADELF=<readelf> -DPROGRAM=<elf> -P expect_static_arm_program.cmake
# Fails unless PROGRAM is a 32-bit Arm executable without a program interpreter, i.e. statically linked.
execute_process(COMMAND ${READELF} --file-header --program-headers ${PROGRAM}
                RESULT_VARIABLE exit_code OUTPUT_VARIABLE headers ERROR_VARIABLE err)
if(NOT exit_code EQUAL 0)
  message(FATAL_ERROR "${READELF} failed on ${PROGRAM}: ${err}")
endif()
if(NOT headers MATCHES "Class: +ELF32" OR NOT headers MATCHES "Machine: +ARM")
  message(FATAL_ERROR "${PROGRAM} is not a 32-bit Arm ELF file:\n${headers}")
endif()
if(headers MATCHES "INTERP")
  message(FATAL_ERROR "${PROGRAM} asks for a program interpreter: it is linked dynamically:\n${headers}")
endif()
