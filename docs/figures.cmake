# Renders one lesson's figures for its docs page: for every variant the final colour and
# stencil pictures, and a snapshot after each named pass (--passes). OPTIONS (optional): more
# flags for every run, one string (add_lesson's FIGURE_OPTIONS, e.g. "--stencil-view bits").
include(${CMAKE_CURRENT_LIST_DIR}/../tests/variants.cmake)
lesson_variants(${EXE} variants)
separate_arguments(options UNIX_COMMAND "${OPTIONS}")
file(REMOVE_RECURSE ${OUT})
foreach(variant IN LISTS variants)
  message(STATUS "figures: ${variant}")
  execute_process(COMMAND ${EXE} --headless --quiet --size ${SIZE} --time ${TIME} --variant ${variant}
                          --out ${OUT}/${variant}.png --stencil-out ${OUT}/${variant}.stencil.png
                          --passes ${OUT}/${variant} ${options}
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${EXE} --variant ${variant} failed (${rc})")
  endif()
  file(REMOVE ${OUT}/${variant}.stencil.raw.png)  # the pages show pictures, not raw values
endforeach()
