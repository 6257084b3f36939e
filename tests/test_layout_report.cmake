# ctest TestLayout.EachTestLinksOnlyItsModule: prints the findings of
# rollspin_check_test_layout (tests/test_layout.cmake), written at configure
# time, and fails when there is any. cmake -DREPORT=<file> -P this file.
file(READ "${REPORT}" findings)
if(findings STREQUAL "")
  message(STATUS "Test layout: every test target links only its module (tests/<m>/ mirrors src/<m>/)")
else()
  message(FATAL_ERROR "Test layout (docs/design.md, Testing):\n${findings}")
endif()
