# Writes the ctest file of one GoogleTest program, run after every link
# (tests/CMakeLists.txt, dermis_add_test_program):
#   cmake -DEXE=... -DOUT=... -DLABEL=unit|render|cli -DSOURCES=a.cpp|b.cpp
#         [-DTEST_ENVIRONMENT=VAR=VALUE]
#         [-DSUITE_ENVIRONMENT_REGEX=REGEX -DSUITE_ENVIRONMENT=VAR=VALUE] -P DiscoverTestGroups.cmake
# (the second environment replaces the first for the tests whose names match)
#
# A test declared in its source, on a comment line above its TEST or TEST_F
# line ("// ctest: slow content window cost=S"), is a ctest test of its own,
# with those labels and that cost. The other tests of a suite run together as
# one ctest test named after the suite (`--gtest_filter=Suite.*` less the
# declared ones): one process instead of one per test, which saves each test
# the program's start-up (about 0.5 s: OpenImageIO's 270 shared libraries),
# the GL context and the shaders (docs/testing.md, "The suite's time").
cmake_policy(VERSION 3.25)

foreach(required EXE OUT LABEL)
  if(NOT DEFINED ${required})
    message(FATAL_ERROR "DiscoverTestGroups.cmake: ${required} is not set")
  endif()
endforeach()

# Milliseconds a test of each kind takes inside its group on the 2-core
# machine (the groups' COST, so that a fresh clone starts the long ones
# first): measured, the render groups' 117 tests took 401 s (3.4 s each) and
# the command-line groups' 62 took 185 s (3.0 s each).
set(typical_ms_unit 50)
set(typical_ms_render 3400)
set(typical_ms_cli 3000)
set(typical_ms "${typical_ms_${LABEL}}")
if(typical_ms STREQUAL "")
  message(FATAL_ERROR "DiscoverTestGroups.cmake: LABEL is ${LABEL}; expected unit, render or cli")
endif()

# ---- what the sources declare ----------------------------------------------
set(declared_tests "")
string(REPLACE "|" ";" SOURCES "${SOURCES}")
foreach(source IN LISTS SOURCES)
  file(STRINGS "${source}" lines REGEX "^(// ctest:|TEST(_F)?\\()")
  set(pending "")
  foreach(line IN LISTS lines)
    if(line MATCHES "^// ctest:(.*)$")
      set(pending "${CMAKE_MATCH_1}")
      continue()
    endif()
    if(pending STREQUAL "" OR NOT line MATCHES "^TEST(_F)?\\(([A-Za-z0-9_]+), *([A-Za-z0-9_]+)\\)")
      set(pending "")
      continue()
    endif()
    set(test "${CMAKE_MATCH_2}.${CMAKE_MATCH_3}")
    separate_arguments(words UNIX_COMMAND "${pending}")
    set(labels ${LABEL})
    set(cost "")
    foreach(word IN LISTS words)
      if(word MATCHES "^cost=([0-9]+)$")
        set(cost "${CMAKE_MATCH_1}")
      elseif(word MATCHES "^(slow|content|window)$")
        list(APPEND labels ${word})
      else()
        message(FATAL_ERROR "${source}: '// ctest:' above ${test} has '${word}'; expected slow, content, window "
                            "or cost=SECONDS")
      endif()
    endforeach()
    list(APPEND declared_tests "${test}")
    string(REPLACE ";" "\\;" "labels_of_${test}" "${labels}")
    set("cost_of_${test}" "${cost}")
    set(pending "")
  endforeach()
endforeach()

# ---- what the program holds ---------------------------------------------------
execute_process(COMMAND "${EXE}" --gtest_list_tests OUTPUT_VARIABLE listing RESULT_VARIABLE status
                ERROR_VARIABLE errors TIMEOUT 60)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${EXE} --gtest_list_tests failed (${status}): ${errors}")
endif()
string(REPLACE ";" "\\;" listing "${listing}")
string(REPLACE "\n" ";" listing "${listing}")
set(suites "")
set(suite "")
foreach(line IN LISTS listing)
  # gtest_main's banner comes first; "# GetParam() = ..." and "# TypeParam = ..."
  # follow names.
  string(REGEX REPLACE " *#.*$" "" line "${line}")
  if(line STREQUAL "")
    continue()
  elseif(line MATCHES "^  (.+)$" AND NOT suite STREQUAL "")
    list(APPEND "tests_of_${suite}" "${CMAKE_MATCH_1}")
  elseif(line MATCHES "^(.+)\\.$")
    set(suite "${CMAKE_MATCH_1}")
    list(APPEND suites "${suite}")
  elseif(NOT suite STREQUAL "")
    message(FATAL_ERROR "${EXE} --gtest_list_tests: cannot read '${line}'")
  endif()
endforeach()

# ---- the ctest file -------------------------------------------------------------
get_filename_component(directory "${EXE}" DIRECTORY)
set(text "")
macro(add_ctest name filter labels cost skip)
  string(APPEND text "add_test([=[${name}]=] \"${EXE}\" [==[--gtest_filter=${filter}]==])\n"
                     "set_tests_properties([=[${name}]=] PROPERTIES WORKING_DIRECTORY \"${directory}\" "
                     "LABELS \"${labels}\"")
  if(NOT "${cost}" STREQUAL "")
    string(APPEND text " COST ${cost}")
  endif()
  if(${skip})
    string(APPEND text " SKIP_REGULAR_EXPRESSION [==[\\[  SKIPPED \\]]==]")
  endif()
  set(environment "${TEST_ENVIRONMENT}")
  if(NOT "${SUITE_ENVIRONMENT_REGEX}" STREQUAL "" AND "${name}" MATCHES "${SUITE_ENVIRONMENT_REGEX}")
    set(environment "${SUITE_ENVIRONMENT}")
  endif()
  if(NOT "${environment}" STREQUAL "")
    string(APPEND text " ENVIRONMENT [==[${environment}]==]")
  endif()
  string(APPEND text ")\n")
  list(APPEND names "${name}")
endmacro()

set(names "")
set(found_declared "")
foreach(suite IN LISTS suites)
  set(grouped "")
  set(excluded "")
  foreach(test IN LISTS "tests_of_${suite}")
    set(full "${suite}.${test}")
    if(full IN_LIST declared_tests)
      add_ctest("${full}" "${full}" "${labels_of_${full}}" "${cost_of_${full}}" TRUE)
      list(APPEND found_declared "${full}")
      list(APPEND excluded "${full}")
    else()
      list(APPEND grouped "${full}")
    endif()
  endforeach()
  list(LENGTH grouped count)
  if(count EQUAL 1)
    # One test left: its own name, and a skip shows as skipped.
    add_ctest("${grouped}" "${grouped}" "${LABEL}" "" TRUE)
  elseif(count GREATER 1)
    # A skip inside a group is one test of many: the group's status is its
    # tests' (GoogleTest's "[  SKIPPED ]" lines are in its output).
    list(JOIN excluded ":" negative)
    set(filter "${suite}.*")
    if(NOT negative STREQUAL "")
      string(APPEND filter ":-${negative}")
    endif()
    math(EXPR cost "(${count} * ${typical_ms} + 999) / 1000")  # whole seconds, rounded up
    add_ctest("${suite}" "${filter}" "${LABEL}" "${cost}" FALSE)
  endif()
endforeach()

foreach(test IN LISTS declared_tests)
  if(NOT test IN_LIST found_declared)
    message(FATAL_ERROR "'// ctest:' declares ${test}, which ${EXE} does not hold")
  endif()
endforeach()

file(WRITE "${OUT}.new" "${text}")
file(RENAME "${OUT}.new" "${OUT}")
# The names, one per line, for CtestNames.EachNameIsOneTest.
list(JOIN names "\n" names_text)
file(WRITE "${OUT}.names" "${names_text}\n")
