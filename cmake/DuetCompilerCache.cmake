# Compile through ccache when it is installed: CI builds every preset from a fresh clone, and ccache keeps that fast.
# Not for firmware: its objects come with the call graphs (-fcallgraph-info=su, the .ci files) that the worst-case
# stack analysis reads (ports/cortex-m/worst_case_stack.py), which ccache 4.7 does not keep: a cache hit would
# leave them out and fail the analysis.
find_program(DUET_CCACHE ccache)
if(DUET_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER AND NOT DUET_TARGET MATCHES "^m4-")
  set(CMAKE_C_COMPILER_LAUNCHER "${DUET_CCACHE}")
  set(CMAKE_CXX_COMPILER_LAUNCHER "${DUET_CCACHE}")
endif()
