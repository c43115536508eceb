# Boots a firmware image on QEMU's mps2-an386 in deterministic time (-icount) and checks what it did.
#
#   cmake -DQEMU=qemu-system-arm -DIMAGE=<elf> [-DEXPECTED_OUTPUT=<file>] [-DEXPECTED_EXIT_CODE=<n>]
#         [-DTIMEOUT=<seconds>] [-DICOUNT_SHIFT=<n>] [-DINPUT=<file>] -P run_in_qemu.cmake
#
# Fails unless QEMU exits within TIMEOUT seconds (default 20) with EXPECTED_EXIT_CODE (default 0) and, if
# EXPECTED_OUTPUT is given, the console output (UART0) equals that file byte for byte. INPUT (default: nothing) is
# what the firmware receives on UART0.
if(NOT DEFINED TIMEOUT)
  set(TIMEOUT 20)
endif()
if(NOT DEFINED INPUT)
  set(INPUT /dev/null)
endif()
if(NOT DEFINED ICOUNT_SHIFT)
  set(ICOUNT_SHIFT 3)
endif()
if(NOT DEFINED EXPECTED_EXIT_CODE)
  set(EXPECTED_EXIT_CODE 0)
endif()

# Prints the diagnosis on one line (FATAL_ERROR's text is wrapped) and fails.
function(fail diagnosis)
  message("run_in_qemu: ${diagnosis}")
  message(FATAL_ERROR "${IMAGE} failed its check")
endfunction()

# shift=N: one guest instruction is 2^N ns of virtual time (3 by default). align=off and sleep=off decouple virtual time from the
# host's clock, so every run executes the same instructions and sees the same interrupts.
execute_process(
  COMMAND ${QEMU} -machine mps2-an386 -nographic -monitor none -serial stdio
          -semihosting-config enable=on,target=native -icount shift=${ICOUNT_SHIFT},align=off,sleep=off -kernel ${IMAGE}
  INPUT_FILE ${INPUT}
  OUTPUT_VARIABLE output
  ERROR_VARIABLE errors
  RESULT_VARIABLE exit_code
  TIMEOUT ${TIMEOUT})

message("${output}")
if(errors)
  message("QEMU said: ${errors}")
endif()
if(NOT exit_code STREQUAL EXPECTED_EXIT_CODE)
  fail("expected exit code ${EXPECTED_EXIT_CODE}, got '${exit_code}'")
endif()
if(DEFINED EXPECTED_OUTPUT)
  file(READ ${EXPECTED_OUTPUT} expected)
  if(NOT output STREQUAL expected)
    fail("the console output differs from ${EXPECTED_OUTPUT}, which expects:\n${expected}")
  endif()
endif()
