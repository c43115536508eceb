# GoogleTest for programs that run on Linux (the PC, or armhf under qemu-arm).
# The host uses Debian's prebuilt libraries; a cross build compiles GoogleTest from the sources Debian ships.
if(CMAKE_CROSSCOMPILING)
  set(INSTALL_GTEST OFF CACHE BOOL "" FORCE)
  add_subdirectory(/usr/src/googletest "${CMAKE_BINARY_DIR}/googletest" EXCLUDE_FROM_ALL SYSTEM)
  foreach(library gtest gtest_main gmock gmock_main)
    target_compile_options(${library} PRIVATE -w)  # not our code: its warnings are noise here
  endforeach()
else()
  find_package(GTest REQUIRED)
endif()
include(GoogleTest)

# duet_add_unit_test(<name> SOURCES ... LIBRARIES ...): one GoogleTest executable whose tests ctest lists one by one.
function(duet_add_unit_test name)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "" "SOURCES;LIBRARIES")
  add_executable(${name} ${ARG_SOURCES})
  duet_target_warnings(${name})
  target_link_libraries(${name} PRIVATE ${ARG_LIBRARIES} GTest::gtest_main GTest::gmock)
  gtest_discover_tests(${name} DISCOVERY_MODE PRE_TEST)
endfunction()
