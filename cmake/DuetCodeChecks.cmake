# Code checks for the host build tree:
#   format-check  fails when a C++ file differs from what clang-format (.clang-format) makes of it
#   format        rewrites the files as clang-format lays them out
#   tidy          runs clang-tidy (.clang-tidy) on every host source file in this build
# ctest runs format-check as the test code_format. clang-tidy takes about a minute on 2 cores for even the first few
# files and grows with the code, so it is a target to run before review, not a test.
file(GLOB_RECURSE duet_cpp_files CONFIGURE_DEPENDS
     LIST_DIRECTORIES false RELATIVE "${PROJECT_SOURCE_DIR}"
     "${PROJECT_SOURCE_DIR}/src/*.[ch]pp" "${PROJECT_SOURCE_DIR}/ports/*.[ch]pp" "${PROJECT_SOURCE_DIR}/apps/*.[ch]pp"
     "${PROJECT_SOURCE_DIR}/tests/*.[ch]pp" "${PROJECT_SOURCE_DIR}/bench/*.[ch]pp")
list(FILTER duet_cpp_files EXCLUDE REGEX "/generated/")  # duet gen's output, laid out by the generator

find_program(DUET_CLANG_FORMAT NAMES clang-format clang-format-14)
if(DUET_CLANG_FORMAT)
  add_custom_target(format-check
    COMMAND ${DUET_CLANG_FORMAT} --dry-run --Werror ${duet_cpp_files}
    WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}" COMMENT "Checking the layout of ${PROJECT_NAME}'s C++ files" VERBATIM)
  add_custom_target(format
    COMMAND ${DUET_CLANG_FORMAT} -i ${duet_cpp_files}
    WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}" COMMENT "Laying out ${PROJECT_NAME}'s C++ files" VERBATIM)
  add_test(NAME code_format COMMAND ${DUET_CLANG_FORMAT} --dry-run --Werror ${duet_cpp_files}
           WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}")
endif()

find_program(DUET_RUN_CLANG_TIDY NAMES run-clang-tidy run-clang-tidy-14)
if(DUET_RUN_CLANG_TIDY)
  # Only the project's own files: the regular expression matches source paths in compile_commands.json.
  set(tidy_command ${DUET_RUN_CLANG_TIDY} -quiet -p "${CMAKE_BINARY_DIR}" "${PROJECT_SOURCE_DIR}/(src|apps|tests|bench)/")
  add_custom_target(tidy COMMAND ${tidy_command} COMMENT "Running clang-tidy on the host sources" VERBATIM)
endif()
