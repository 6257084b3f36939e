# CPack pre-build script (CPACK_PRE_BUILD_SCRIPTS in the top-level
# CMakeLists.txt): in a Debian package, man pages are compressed with
# `gzip -9n` (Debian policy 12.1; -n stores no name or time stamp, so the
# .deb is the same from one build to the next). It runs on the staged tree,
# after the install into it and before the package is made; other generators
# and `cmake --install` keep the page uncompressed.
if(NOT CPACK_GENERATOR STREQUAL "DEB")
  return()
endif()
find_program(ROLLSPIN_GZIP gzip)
if(NOT ROLLSPIN_GZIP)
  message(FATAL_ERROR "cpack -G DEB compresses the man pages with gzip, which is not on PATH (apt-get install gzip)")
endif()
file(GLOB_RECURSE staged LIST_DIRECTORIES false "${CPACK_TEMPORARY_DIRECTORY}/*")
foreach(page IN LISTS staged)
  if(page MATCHES "/share/man/([a-z_]+/)?man[1-9n]/[^/]+$" AND NOT page MATCHES "\\.gz$")
    execute_process(COMMAND "${ROLLSPIN_GZIP}" -9nf "${page}" RESULT_VARIABLE status)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "gzip -9n ${page} failed (${status})")
    endif()
  endif()
endforeach()
