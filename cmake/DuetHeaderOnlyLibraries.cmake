# duet_header_only_library(<target> PACKAGE <debian-package> HEADERS <path under /usr/include>...)
#
# Header-only Debian libraries (CLI11, nlohmann-json, Boost's Beast and Asio) serve the host and the armhf Linux build alike. The host
# finds them in /usr/include already. A cross build must not search /usr/include, which holds the PC's C library
# headers, so it sees just the library's own headers through a folder of symbolic links in the build tree.
function(duet_header_only_library target)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "PACKAGE" "HEADERS")
  if(TARGET ${target})
    return()
  endif()
  add_library(${target} INTERFACE)
  set(links "${CMAKE_BINARY_DIR}/header-only-include")
  foreach(header IN LISTS ARG_HEADERS)
    if(NOT EXISTS "/usr/include/${header}")
      message(FATAL_ERROR "/usr/include/${header} is missing: run scripts/setup.sh (it installs ${ARG_PACKAGE})")
    endif()
    if(CMAKE_CROSSCOMPILING)
      get_filename_component(parent "${links}/${header}" DIRECTORY)
      file(MAKE_DIRECTORY "${parent}")
      file(CREATE_LINK "/usr/include/${header}" "${links}/${header}" SYMBOLIC)
    endif()
  endforeach()
  if(CMAKE_CROSSCOMPILING)
    target_include_directories(${target} SYSTEM INTERFACE "${links}")
  endif()
endfunction()

duet_header_only_library(duet_cli11 PACKAGE libcli11-dev HEADERS CLI)
duet_header_only_library(duet_nlohmann_json PACKAGE nlohmann-json3-dev HEADERS nlohmann)
duet_header_only_library(duet_boost_beast PACKAGE libboost-dev HEADERS boost)
# GCC 12 at -O3 warns of a null dereference in Asio's scheduler and out-of-bounds indices in Beast's inflate tables:
# middle-end warnings on code inlined into ours, which system headers do not silence.
target_compile_options(duet_boost_beast INTERFACE $<$<CXX_COMPILER_ID:GNU>:-Wno-null-dereference -Wno-array-bounds>)
