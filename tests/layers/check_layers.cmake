# Proves the engine's layering (engine/CMakeLists.txt): for every layer, a
# file that includes one of its own headers preprocesses with that layer's
# include view, and a file that includes a header of any layer it may not use
# fails with "No such file". Run by ctest as
#   cmake -DCXX=<compiler> -DVIEWS=<build>/layers -DSHADERS=<shaders dir>
#         -DEXTRA_INCLUDES=<third-party include dirs> -P check_layers.cmake
# A failure names the layer pair. Preprocessing (-E) is enough: an include
# that cannot be found is the same fatal error that fails the build.
cmake_minimum_required(VERSION 3.25)
file(STRINGS ${VIEWS}/layers.txt rows)
set(layers "")
foreach(row IN LISTS rows)
  string(REPLACE " " ";" fields "${row}")
  list(GET fields 0 layer)
  list(GET fields 1 header)
  list(GET fields 2 closure)
  string(REPLACE "," ";" closure "${closure}")
  list(APPEND layers ${layer})
  set(header_${layer} ${header})
  set(closure_${layer} ${closure})
endforeach()

set(extraFlags "")
foreach(directory IN LISTS EXTRA_INCLUDES)
  if(directory)
    list(APPEND extraFlags -I${directory})
  endif()
endforeach()
set(probe ${VIEWS}/probe.cpp)
set(failures 0)
set(checked 0)
foreach(layer IN LISTS layers)
  foreach(other IN LISTS layers)
    # A layer's own header proves its view works; the build itself proves
    # that each layer sees the ones it uses. What needs proving here is
    # that every other layer is out of sight.
    if(other IN_LIST closure_${layer} AND NOT other STREQUAL layer)
      continue()
    endif()
    file(WRITE ${probe} "#include \"${header_${other}}\"\n")
    execute_process(COMMAND ${CXX} -std=c++17 -E -o /dev/null -I${VIEWS}/${layer} -I${SHADERS} ${extraFlags} ${probe}
                    RESULT_VARIABLE result ERROR_VARIABLE errors OUTPUT_QUIET)
    math(EXPR checked "${checked} + 1")
    if(other STREQUAL layer)
      if(NOT result EQUAL 0)
        message(SEND_ERROR "layer ${layer} may include ${header_${other}} but it does not preprocess:\n${errors}")
        math(EXPR failures "${failures} + 1")
      endif()
    else()
      string(FIND "${errors}" "${header_${other}}: No such file" missing)
      if(result EQUAL 0 OR missing EQUAL -1)
        message(SEND_ERROR "layer ${layer} must not see ${header_${other}} (layer ${other} is above or beside it), "
                           "but including it did not fail as a missing file (exit ${result}):\n${errors}")
        math(EXPR failures "${failures} + 1")
      endif()
    endif()
  endforeach()
endforeach()
file(REMOVE ${probe})
message(STATUS "layers: ${checked} pairs checked, ${failures} failed")
