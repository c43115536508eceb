# Compile through ccache when it is installed: CI builds every preset from a fresh clone, and ccache keeps that fast.
find_program(DUET_CCACHE ccache)
if(DUET_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  set(CMAKE_C_COMPILER_LAUNCHER "${DUET_CCACHE}")
  set(CMAKE_CXX_COMPILER_LAUNCHER "${DUET_CCACHE}")
endif()
