# Renders one lesson's figures for its docs page: for every variant the final colour and
# stencil pictures, and a snapshot after each named pass (--passes). OPTIONS (optional): more
# flags for every run, one string (add_lesson's FIGURE_OPTIONS, e.g. "--stencil-view bits").
# With PAGE (the lesson's docs page), only what the page shows is kept: the passes are written
# only for the variants whose pass folder it names, the raw stencil (`.stencil.raw.png`, grey =
# the value) is kept where it names one, and every file it does not name is removed. VARIANTS
# (optional): only these variants (tests/docs/check_figures.py renders the ones the pages link).
include(${CMAKE_CURRENT_LIST_DIR}/../tests/variants.cmake)
if(DEFINED VARIANTS)
  set(variants ${VARIANTS})
else()
  lesson_variants(${EXE} variants)
endif()
separate_arguments(options UNIX_COMMAND "${OPTIONS}")
file(REMOVE_RECURSE ${OUT})
get_filename_component(id ${OUT} NAME)
if(DEFINED PAGE)
  file(READ ${PAGE} page)
  string(REGEX MATCHALL "\\(figures/${id}/[^)]+\\)" shown "${page}")  # ![](figures/<id>/...)
  list(TRANSFORM shown REPLACE "^\\(figures/${id}/(.*)\\)$" "\\1")
endif()
foreach(variant IN LISTS variants)
  message(STATUS "figures: ${variant}")
  set(passes --passes ${OUT}/${variant})
  if(DEFINED PAGE AND NOT shown MATCHES "(^|;)${variant}/")
    set(passes)
  endif()
  execute_process(COMMAND ${EXE} --headless --quiet --size ${SIZE} --time ${TIME} --variant ${variant}
                          --out ${OUT}/${variant}.png --stencil-out ${OUT}/${variant}.stencil.png
                          ${passes} ${options}
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${EXE} --variant ${variant} failed (${rc})")
  endif()
  if(NOT DEFINED PAGE)
    file(REMOVE ${OUT}/${variant}.stencil.raw.png)  # the pages show pictures, not raw values
  endif()
endforeach()
if(DEFINED PAGE)
  get_filename_component(out ${OUT} ABSOLUTE)
  file(GLOB_RECURSE written RELATIVE ${out} ${out}/*)
  foreach(f IN LISTS written)
    list(FIND shown ${f} i)
    if(i EQUAL -1)
      file(REMOVE ${OUT}/${f})
    endif()
  endforeach()
  foreach(f IN LISTS shown)
    if(NOT EXISTS ${OUT}/${f} AND NOT DEFINED VARIANTS)  # with VARIANTS the caller checks its own
      message(FATAL_ERROR "${PAGE} shows figures/${id}/${f}, which ${EXE} did not write")
    endif()
  endforeach()
endif()
