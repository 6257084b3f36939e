# The test layout rule (docs/design.md, "Testing"), checked from the CMake
# targets after every test is declared: tests/<m>/ holds the tests of src/<m>/,
# and a target there links only what module m reaches.
#
#   allowed(m) = the libraries of src/<m>/ and every library they link,
#                transitively (PRIVATE links included: they are linked);
#              + rollspin_kinematics and what it reaches, for a target
#                declared ORACLE (the independent rigid-body oracle);
#              + test support (tests/support, tests/<m>/ helpers), which is
#                walked through: its own links count as the test's.
#
# tests/cli/ is exempt (the binary as a subprocess: it may read what any
# module writes). Every src/<m>/ needs a tests/<m>/ with a test program.
# The findings go to <build>/tests/test_layout.txt, one line each; the ctest
# TestLayout.EachTestLinksOnlyItsModule fails and prints them when there is
# any (tests/test_layout_report.cmake).

# A target's own links, aliases resolved, generator expressions other than
# $<LINK_ONLY:x> (a static library's PRIVATE link, linked all the same) dropped.
function(_rollspin_direct_links target out)
  set(links "")
  get_target_property(type ${target} TYPE)
  get_target_property(imported ${target} IMPORTED)
  if(NOT imported AND NOT type STREQUAL "INTERFACE_LIBRARY")
    get_target_property(own ${target} LINK_LIBRARIES)
    if(own)
      list(APPEND links ${own})
    endif()
  endif()
  get_target_property(iface ${target} INTERFACE_LINK_LIBRARIES)
  if(iface)
    list(APPEND links ${iface})
  endif()
  set(result "")
  foreach(link IN LISTS links)
    if(link MATCHES "^\\$<LINK_ONLY:(.+)>$")
      set(link "${CMAKE_MATCH_1}")
    endif()
    if(link MATCHES "^\\$<" OR NOT TARGET "${link}")
      continue()
    endif()
    get_target_property(aliased "${link}" ALIASED_TARGET)
    if(aliased)
      set(link "${aliased}")
    endif()
    list(APPEND result "${link}")
  endforeach()
  set(${out} "${result}" PARENT_SCOPE)
endfunction()

# Every target reached from `roots` (the roots included).
function(_rollspin_link_closure out)
  set(seen "")
  set(queue ${ARGN})
  while(queue)
    list(POP_FRONT queue t)
    if(t IN_LIST seen)
      continue()
    endif()
    list(APPEND seen "${t}")
    _rollspin_direct_links("${t}" next)
    list(APPEND queue ${next})
  endwhile()
  set(${out} "${seen}" PARENT_SCOPE)
endfunction()

# The module of a target built from src/<m>/ (its SOURCE_DIR), else "".
function(_rollspin_module_of target out)
  set(module "")
  get_target_property(imported ${target} IMPORTED)
  if(NOT imported)
    get_target_property(dir ${target} SOURCE_DIR)
    file(RELATIVE_PATH rel "${PROJECT_SOURCE_DIR}/src" "${dir}")
    if(rel MATCHES "^([a-z_]+)")
      set(module "${CMAKE_MATCH_1}")
    endif()
  endif()
  set(${out} "${module}" PARENT_SCOPE)
endfunction()

function(rollspin_check_test_layout)
  set(findings "")
  # The modules: src/<m>/ folders with a CMakeLists.txt, and their targets.
  file(GLOB module_dirs LIST_DIRECTORIES true "${PROJECT_SOURCE_DIR}/src/*")
  set(modules "")
  foreach(dir IN LISTS module_dirs)
    if(IS_DIRECTORY "${dir}" AND EXISTS "${dir}/CMakeLists.txt")
      get_filename_component(m "${dir}" NAME)
      list(APPEND modules ${m})
      get_property(targets_${m} DIRECTORY "${dir}" PROPERTY BUILDSYSTEM_TARGETS)
    endif()
  endforeach()
  _rollspin_link_closure(oracle rollspin_kinematics)

  get_property(test_targets GLOBAL PROPERTY ROLLSPIN_TEST_TARGETS)
  set(folders_with_tests "")
  foreach(test IN LISTS test_targets)
    get_target_property(dir ${test} SOURCE_DIR)
    file(RELATIVE_PATH rel "${PROJECT_SOURCE_DIR}/tests" "${dir}")
    string(REGEX REPLACE "/.*" "" folder "${rel}")
    list(APPEND folders_with_tests ${folder})
    if(folder STREQUAL "cli")
      continue()
    endif()
    if(NOT folder IN_LIST modules)
      list(APPEND findings "${test}: tests/${folder}/ mirrors no module of src/ (unit tests go in tests/<module>/, subprocess tests of the binary in tests/cli/)")
      continue()
    endif()
    _rollspin_link_closure(allowed ${targets_${folder}})
    get_target_property(uses_oracle ${test} ROLLSPIN_TEST_ORACLE)
    if(uses_oracle)
      list(APPEND allowed ${oracle})
    endif()
    _rollspin_link_closure(reached ${test})
    foreach(lib IN LISTS reached)
      _rollspin_module_of(${lib} owner)
      if(owner AND NOT lib IN_LIST allowed)
        set(via "")
        _rollspin_direct_links(${test} direct)
        if(NOT lib IN_LIST direct)
          set(via " (through its other links)")
        endif()
        list(APPEND findings "${test} (tests/${folder}/) links ${lib} of src/${owner}/${via}, which rollspin_${folder}'s libraries do not reach")
      endif()
    endforeach()
  endforeach()
  foreach(m IN LISTS modules)
    if(NOT m IN_LIST folders_with_tests)
      list(APPEND findings "src/${m}/ has no test program in tests/${m}/")
    endif()
  endforeach()

  list(JOIN findings "\n" text)
  file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/test_layout.txt" "${text}")
  if(findings)
    list(LENGTH findings count)
    message(WARNING "Test layout: ${count} finding(s), see ${CMAKE_CURRENT_BINARY_DIR}/test_layout.txt "
                    "(ctest -R TestLayout):\n${text}")
  endif()
  add_test(NAME TestLayout.EachTestLinksOnlyItsModule
           COMMAND ${CMAKE_COMMAND} -DREPORT=${CMAKE_CURRENT_BINARY_DIR}/test_layout.txt
                   -P ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/test_layout_report.cmake)
  set_tests_properties(TestLayout.EachTestLinksOnlyItsModule PROPERTIES LABELS source)
endfunction()
