# Rewrites the goldens of one lesson: every variant, default headless backend.
include(${CMAKE_CURRENT_LIST_DIR}/variants.cmake)
# The goldens are llvmpipe's (common/gl/golden.h): on a machine with a GPU, ask for Mesa's software
# rendering; a lesson refuses to write a golden from any other renderer.
set(ENV{LIBGL_ALWAYS_SOFTWARE} 1)
foreach(vendor /usr/share/glvnd/egl_vendor.d/50_mesa.json /etc/glvnd/egl_vendor.d/50_mesa.json)
  if(EXISTS ${vendor})
    set(ENV{__EGL_VENDOR_LIBRARY_FILENAMES} ${vendor})
    break()
  endif()
endforeach()
lesson_variants(${EXE} variants)
foreach(variant IN LISTS variants)
  execute_process(COMMAND ${EXE} --headless --size ${SIZE} --time ${TIME} --variant ${variant}
                          --golden ${GOLDEN_DIR} --update-golden --quiet RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${EXE} --variant ${variant} failed (${rc})")
  endif()
endforeach()
