# cmake -DCXX=compiler -DSOURCE=hook_check_unit.cpp -DINCLUDES="dir;dir" -P hook_check_test.cmake
# The effects' hooks are checked at compile time (simulate/include/ggsim/effects/hooks.hpp): the unit
# of hook_check_unit.cpp compiles when right (case 0) and stops the build, with the message naming
# its hook, when its declared hook is misspelled (1) or mistyped (2, 4) or its hook undeclared (3).
set(flags -std=c++20 -fsyntax-only)
foreach(dir IN LISTS INCLUDES)
  list(APPEND flags -I${dir})
endforeach()
set(expected
    "0|"
    "1|declares hook::restitution but has no"
    "2|declares hook::restitution but has no"
    "3|has restitution\\(\\) but does not declare hook::restitution"
    "4|declares hook::sizes but lacks double mass")
foreach(entry IN LISTS expected)
  string(REPLACE "|" ";" parts "${entry}")
  list(GET parts 0 case)
  list(LENGTH parts n)
  set(message "")
  if(n GREATER 1)
    list(GET parts 1 message)
  endif()
  execute_process(COMMAND ${CXX} ${flags} -DHOOK_CASE=${case} ${SOURCE} RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(message STREQUAL "")
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "case ${case}: a rightly declared hook does not compile:\n${err}")
    endif()
  elseif(rc EQUAL 0)
    message(FATAL_ERROR "case ${case}: a wrong hook compiled")
  elseif(NOT err MATCHES "${message}")
    message(FATAL_ERROR "case ${case}: the build stopped without naming the hook ('${message}'):\n${err}")
  else()
    message(STATUS "case ${case}: stopped, naming the hook")
  endif()
endforeach()
