# Renders one lesson's figures for its docs page: for every variant the final colour and
# stencil pictures, and a snapshot after each named pass (--passes).
include(${CMAKE_CURRENT_LIST_DIR}/../tests/variants.cmake)
lesson_variants(${EXE} variants)
file(REMOVE_RECURSE ${OUT})
foreach(variant IN LISTS variants)
  message(STATUS "figures: ${variant}")
  execute_process(COMMAND ${EXE} --headless --quiet --size ${SIZE} --time ${TIME} --variant ${variant}
                          --out ${OUT}/${variant}.png --stencil-out ${OUT}/${variant}.stencil.png
                          --passes ${OUT}/${variant}
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${EXE} --variant ${variant} failed (${rc})")
  endif()
  file(REMOVE ${OUT}/${variant}.stencil.raw.png)  # the pages show pictures, not raw values
endforeach()
