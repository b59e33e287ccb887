# Rewrites the goldens of one lesson: every variant, default headless backend.
include(${CMAKE_CURRENT_LIST_DIR}/variants.cmake)
lesson_variants(${EXE} variants)
foreach(variant IN LISTS variants)
  execute_process(COMMAND ${EXE} --headless --size ${SIZE} --time ${TIME} --variant ${variant}
                          --golden ${GOLDEN_DIR} --update-golden --quiet RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${EXE} --variant ${variant} failed (${rc})")
  endif()
endforeach()
