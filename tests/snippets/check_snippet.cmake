# cmake -D MODULE=shadow_volume -D GEOMETRY_DIR=.../common/geometry -D WORK_DIR=... -D CXX=c++
#       -P check_snippet.cmake
# Copies geometry/MODULE.h (and .cpp) and the modules its "Depends on:" line names into an empty
# WORK_DIR/geometry, compiles every .cpp there alone (-std=c++17, warnings as errors, GLM from the
# system; no POSIX M_ constant) and links the objects into a shared library with no undefined symbol. Fails with the
# compiler's words when the module needs more than it says.
foreach(var MODULE GEOMETRY_DIR WORK_DIR CXX)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_snippet.cmake: ${var} is not set")
  endif()
endforeach()

set(header "${GEOMETRY_DIR}/${MODULE}.h")
if(NOT EXISTS "${header}")
  message(FATAL_ERROR "snippet ${MODULE}: no ${header}")
endif()
file(STRINGS "${header}" lines REGEX "^// Depends on: ")
list(LENGTH lines count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "snippet ${MODULE}: ${MODULE}.h needs exactly one '// Depends on: ...' line, has ${count}")
endif()
# "// Depends on: GLM, mesh, adjacency (C++17)." -> GLM;mesh;adjacency
string(REGEX REPLACE "^// Depends on: ([^(]*)\\(.*$" "\\1" names "${lines}")
if(names STREQUAL lines)
  message(FATAL_ERROR "snippet ${MODULE}: the Depends on line does not end in '(C++17).': ${lines}")
endif()
string(REPLACE "," ";" names "${names}")
set(modules ${MODULE})
foreach(name IN LISTS names)
  string(STRIP "${name}" name)
  if(name STREQUAL "GLM" OR name STREQUAL "the standard library only")
    continue()
  endif()
  if(NOT EXISTS "${GEOMETRY_DIR}/${name}.h")
    message(FATAL_ERROR "snippet ${MODULE}: it names '${name}', which is no module of ${GEOMETRY_DIR}")
  endif()
  list(APPEND modules ${name})
endforeach()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}/geometry")
set(objects "")
foreach(m IN LISTS modules)
  file(COPY "${GEOMETRY_DIR}/${m}.h" DESTINATION "${WORK_DIR}/geometry")
  if(EXISTS "${GEOMETRY_DIR}/${m}.cpp")
    file(COPY "${GEOMETRY_DIR}/${m}.cpp" DESTINATION "${WORK_DIR}/geometry")
  endif()
endforeach()
# POSIX's <math.h> constants (M_PI...) compile with GCC and Clang on Linux, so the compiler cannot
# catch them: they are looked for in the code, comments left out.
file(GLOB copied "${WORK_DIR}/geometry/*")
foreach(f IN LISTS copied)
  file(STRINGS "${f}" lines)
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "//.*" "" code "${line}")
    if(code MATCHES "(^|[^A-Za-z0-9_])(M_[A-Z][A-Z0-9_]*)")
      get_filename_component(name "${f}" NAME)
      message(FATAL_ERROR "snippet ${MODULE}: ${name} uses ${CMAKE_MATCH_2}, a POSIX constant, not C++17: ${line}")
    endif()
  endforeach()
endforeach()

foreach(m IN LISTS modules)
  if(NOT EXISTS "${WORK_DIR}/geometry/${m}.cpp")
    continue()
  endif()
  execute_process(
    COMMAND "${CXX}" -std=c++17 -Wall -Wextra -Wpedantic -Werror -fPIC -O0 -I "${WORK_DIR}"
            -c "${WORK_DIR}/geometry/${m}.cpp" -o "${WORK_DIR}/${m}.o"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "snippet ${MODULE}: ${m}.cpp does not compile with only ${modules} as C++17:\n${out}")
  endif()
  list(APPEND objects "${WORK_DIR}/${m}.o")
endforeach()
execute_process(
  COMMAND "${CXX}" -shared -Wl,--no-undefined -o "${WORK_DIR}/lib${MODULE}.so" ${objects}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "snippet ${MODULE}: ${modules} do not link on their own:\n${out}")
endif()
message(STATUS "snippet ${MODULE}: ${modules} compile as C++17 and link alone")
