# Golden tests for a lesson, discovered after the build from the lesson's own
# --list-variants, so the variants are declared in one place: the lesson file.
#
# Every variant is rendered at GOLDEN_SIZE and GOLDEN_TIME on each headless backend and
# compared with tests/golden/<lesson>/<variant>.png (colour, within tolerance) and
# .stencil.png (exact). The first variant is also shown in a real window under Xvfb and
# the window's pixels compared with the same golden.

set(GOLDEN_SIZE 320x240)
set(GOLDEN_TIME 1.0)
set(GOLDEN_ROOT ${PROJECT_SOURCE_DIR}/tests/golden)
find_program(XVFB_RUN xvfb-run)
# The goldens are llvmpipe's: on a machine with a GPU, the EGL golden tests ask glvnd for Mesa's
# EGL and Mesa for software rendering (the lesson skips the comparison on any other renderer).
find_file(STENCIL_MESA_EGL_VENDOR 50_mesa.json PATHS /usr/share/glvnd/egl_vendor.d /etc/glvnd/egl_vendor.d
          NO_DEFAULT_PATH)

function(add_golden_tests id)
  set(backends egl)
  if(OSMESA_FOUND)
    list(PREPEND backends osmesa)
  endif()
  set(discovered ${CMAKE_CURRENT_BINARY_DIR}/${id}_golden_tests.cmake)
  add_custom_command(TARGET ${id} POST_BUILD
    COMMAND ${CMAKE_COMMAND}
      -D EXE=$<TARGET_FILE:${id}> -D ID=${id} -D OUT=${discovered}
      -D GOLDEN_DIR=${GOLDEN_ROOT}/${id} -D ARTIFACTS=${CMAKE_BINARY_DIR}/golden-artifacts/${id}
      -D "BACKENDS=${backends}" -D SIZE=${GOLDEN_SIZE} -D TIME=${GOLDEN_TIME} -D XVFB_RUN=${XVFB_RUN}
      -D MESA_EGL_VENDOR=${STENCIL_MESA_EGL_VENDOR}
      -D TIMEOUT_SCALE=${STENCIL_TIMEOUT_SCALE}
      -P ${PROJECT_SOURCE_DIR}/tests/discover_golden_tests.cmake
    BYPRODUCTS ${discovered}
    VERBATIM)
  set(wrapper ${CMAKE_CURRENT_BINARY_DIR}/${id}_golden_include.cmake)
  file(WRITE ${wrapper}
    "if(EXISTS \"${discovered}\")\n  include(\"${discovered}\")\n"
    "else()\n  add_test(${id}_NOT_BUILT ${id}_NOT_BUILT)\nendif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${wrapper})
endfunction()
