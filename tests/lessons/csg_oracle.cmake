# Runs lesson 14 (EXE) on a scene file (SCENE) with --set method=METHOD --set oracle=1 at SIZE and
# GOLDEN_TIME, and passes when every pixel that disagrees with the CSG ray cast lies on an edge of
# the geometry (oracle_primitive_disagreements + oracle_depth_disagreements == oracle_on_edges).
# With EXPECT_FAILURE it passes only when some pixel off the edges disagrees (a picture known
# wrong). A run that cannot make a GL context (77) is skipped.
execute_process(COMMAND ${EXE} --headless --quiet --stats --size ${SIZE} --time 1 --scene ${SCENE}
                        --set method=${METHOD} --set oracle=1
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 77)
  message("no GL context: skipped")
  return()
endif()
# The lesson's oracle exits 1 when a pixel off the edges disagrees: expected of a known-wrong picture.
if(NOT rc EQUAL 0 AND NOT (EXPECT_FAILURE AND rc EQUAL 1))
  message(FATAL_ERROR "exit ${rc}: ${err}")
endif()
set(counts)
foreach(name primitive_disagreements depth_disagreements on_edges)
  string(REGEX MATCH "\"oracle_${name}\": *([0-9]+)" found "${out}")
  if(NOT found)
    message(FATAL_ERROR "no oracle_${name} in --stats")
  endif()
  set(${name} ${CMAKE_MATCH_1})
endforeach()
math(EXPR off "${primitive_disagreements} + ${depth_disagreements} - ${on_edges}")
message("${SCENE} method ${METHOD} ${SIZE}: ${off} pixels off the edges disagree, ${on_edges} on them")
if(EXPECT_FAILURE AND off EQUAL 0)
  message(FATAL_ERROR "expected the ray cast to disagree off the edges")
elseif(NOT EXPECT_FAILURE AND NOT off EQUAL 0)
  message(FATAL_ERROR "${off} pixels off the edges disagree with the ray cast")
elseif(EXPECT_FAILURE AND NOT rc EQUAL 1)
  message(FATAL_ERROR "the ray cast disagrees off the edges, yet the lesson exited ${rc}, not 1")
endif()
