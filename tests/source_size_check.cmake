# ctest SourceLayout.NoSourceFileOver700Lines (cmake -P, at test time, so an
# edit is seen without reconfiguring): no .cpp in src/ is longer than 700
# lines (issue 40: a file one engineer can carry; the renderer, once 2,325
# lines, is a facade over one file per pass). Run with -DSRC=<src folder>.
set(limit 700)
file(GLOB_RECURSE sources "${SRC}/*.cpp")
set(over "")
foreach(file IN LISTS sources)
  file(READ "${file}" text)
  string(REGEX MATCHALL "\n" newlines "${text}")
  list(LENGTH newlines lines)
  if(lines GREATER limit)
    file(RELATIVE_PATH rel "${SRC}/.." "${file}")
    list(APPEND over "${rel}: ${lines} lines")
  endif()
endforeach()
list(LENGTH sources count)
if(over)
  list(JOIN over "\n  " text)
  message(FATAL_ERROR "over ${limit} lines (split it by concept, docs/design.md):\n  ${text}")
endif()
message(STATUS "${count} .cpp files in src/, none over ${limit} lines")
