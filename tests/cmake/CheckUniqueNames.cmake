# CtestNames.EachNameIsOneTest: no two ctest tests of the GoogleTest programs
# share a name (tests/cmake/DiscoverTestGroups.cmake names a group after its
# suite, and two programs may hold suites of one name: `ctest -R` would then
# run both and the results would not say which is which).
#   cmake -DFILES=a.names|b.names -P CheckUniqueNames.cmake
cmake_policy(VERSION 3.25)
string(REPLACE "|" ";" FILES "${FILES}")
set(seen "")
set(repeated "")
set(read 0)
foreach(file IN LISTS FILES)
  if(NOT EXISTS "${file}")
    # A program not built (tools/setup.sh sanitize builds the unit tests
    # alone) has its own failing <target>_NOT_BUILT test instead.
    message(STATUS "${file} is missing: that program is not built")
    continue()
  endif()
  math(EXPR read "${read} + 1")
  file(STRINGS "${file}" names)
  foreach(name IN LISTS names)
    if(name IN_LIST seen)
      list(APPEND repeated "${name}")
    endif()
    list(APPEND seen "${name}")
  endforeach()
endforeach()
if(read EQUAL 0)
  message(FATAL_ERROR "no test program's names were found: build the tests first")
endif()
list(LENGTH seen count)
if(repeated)
  message(FATAL_ERROR "ctest names used more than once: ${repeated}")
endif()
message(STATUS "${count} ctest names, each used once")
