# duet_target_warnings(<target>): the warning set every duet target compiles with; warnings are errors.
function(duet_target_warnings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wconversion -Wsign-conversion -Wshadow -Wcast-align -Wnon-virtual-dtor
    -Wold-style-cast -Woverloaded-virtual -Wnull-dereference -Wimplicit-fallthrough -Werror
    # Tables are written with designated initializers that leave defaulted members out; GCC 12 warns about that.
    -Wno-missing-field-initializers)
  if(DUET_TARGET MATCHES "^m4-")
    # The Cortex-M4's FPU computes in single precision only: a float promoted to double without a word goes through
    # libgcc's software routines. Firmware says so where it means it (docs/MODELS.md, "Precision").
    target_compile_options(${target} PRIVATE -Wdouble-promotion)
  endif()
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # GCC 12 reports impossible overlaps in std::string's inlined copies at -O3 (GCC bug 105329).
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
endfunction()
