# Run after a lesson is built (see golden_tests.cmake): asks the lesson for its variants
# and writes the ctest file with one golden test per variant and backend.
execute_process(COMMAND ${EXE} --list-variants OUTPUT_VARIABLE listing RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${EXE} --list-variants failed (${rc})")
endif()
string(REPLACE "\n" ";" lines "${listing}")
set(content "# Generated from ${ID} --list-variants; do not edit.\n")
set(first "")
foreach(line IN LISTS lines)
  if(line STREQUAL "")
    continue()
  endif()
  string(REGEX REPLACE "\t.*" "" variant "${line}")
  if(first STREQUAL "")
    set(first ${variant})
  endif()
  foreach(backend IN LISTS BACKENDS)
    set(name golden.${ID}.${variant}.${backend})
    string(APPEND content
      "add_test([=[${name}]=] [=[${EXE}]=] --backend ${backend} --size ${SIZE} --time ${TIME} "
      "--variant [=[${variant}]=] --golden [=[${GOLDEN_DIR}]=] --artifacts [=[${ARTIFACTS}/${variant}-${backend}]=] --quiet)\n"
      "set_tests_properties([=[${name}]=] PROPERTIES SKIP_RETURN_CODE 77 LABELS golden TIMEOUT 60)\n")
  endforeach()
endforeach()

set(name window.${ID}.${first})
if(XVFB_RUN)
  string(APPEND content
    "add_test([=[${name}]=] [=[${XVFB_RUN}]=] -a -s [=[-screen 0 800x600x24]=] [=[${EXE}]=] --backend window "
    "--size ${SIZE} --time ${TIME} --frames 1 --variant [=[${first}]=] --golden [=[${GOLDEN_DIR}]=] "
    "--artifacts [=[${ARTIFACTS}/${first}-window]=] --quiet)\n")
else()
  string(APPEND content "add_test([=[${name}]=] sh -c [=[echo 'xvfb-run is not installed (apt-get install xvfb xauth)'; exit 77]=])\n")
endif()
string(APPEND content "set_tests_properties([=[${name}]=] PROPERTIES SKIP_RETURN_CODE 77 LABELS window TIMEOUT 60)\n")
file(WRITE ${OUT} "${content}")
