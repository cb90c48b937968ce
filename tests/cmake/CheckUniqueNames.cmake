# CtestNames.EachNameIsOneTest: no two ctest tests of the GoogleTest programs
# share a name (tests/cmake/DiscoverTestGroups.cmake names a group after its
# suite, and two programs may hold suites of one name: `ctest -R` would then
# run both and the results would not say which is which).
#   cmake -DFILES=a.names|b.names -P CheckUniqueNames.cmake
cmake_policy(VERSION 3.25)
string(REPLACE "|" ";" FILES "${FILES}")
set(seen "")
set(repeated "")
foreach(file IN LISTS FILES)
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "${file} is missing: build the tests first")
  endif()
  file(STRINGS "${file}" names)
  foreach(name IN LISTS names)
    if(name IN_LIST seen)
      list(APPEND repeated "${name}")
    endif()
    list(APPEND seen "${name}")
  endforeach()
endforeach()
list(LENGTH seen count)
if(repeated)
  message(FATAL_ERROR "ctest names used more than once: ${repeated}")
endif()
message(STATUS "${count} ctest names, each used once")
