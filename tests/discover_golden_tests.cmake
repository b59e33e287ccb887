# Run after a lesson is built (see golden_tests.cmake): asks the lesson for its variants
# and writes the ctest file with one golden test per variant and backend.
include(${CMAKE_CURRENT_LIST_DIR}/variants.cmake)
lesson_variants(${EXE} variants)
list(GET variants 0 first)
set(content "# Generated from ${ID} --list-variants; do not edit.\n")
# Under AddressSanitizer (the debug and clang-sanitize presets) no leak check on EGL or in a
# window: eglTerminate and glfwTerminate unload Mesa's DRI driver, and what the driver still holds
# at exit (2 x 56 B) is then reported with stack frames that name no library, or the wrong one, so
# no suppression can tell it from the lesson's. The OSMesa run of the same variant checks the
# lesson's leaks. Other builds ignore the variable.
set(no_leak_check "ASAN_OPTIONS=detect_leaks=0")
math(EXPR timeout "60 * ${TIMEOUT_SCALE}")  # seconds, scaled for slow builds (STENCIL_TIMEOUT_SCALE)
foreach(variant IN LISTS variants)
  foreach(backend IN LISTS BACKENDS)
    set(name golden.${ID}.${variant}.${backend})
    string(APPEND content
      "add_test([=[${name}]=] [=[${EXE}]=] --backend ${backend} --size ${SIZE} --time ${TIME} "
      "--variant [=[${variant}]=] --golden [=[${GOLDEN_DIR}]=] --artifacts [=[${ARTIFACTS}/${variant}-${backend}]=] --quiet)\n"
      "set_tests_properties([=[${name}]=] PROPERTIES SKIP_RETURN_CODE 77 LABELS golden TIMEOUT ${timeout})\n")
    if(backend STREQUAL "egl")
      set(environment "LIBGL_ALWAYS_SOFTWARE=1")
      if(MESA_EGL_VENDOR)
        string(APPEND environment ";__EGL_VENDOR_LIBRARY_FILENAMES=${MESA_EGL_VENDOR}")
      endif()
      string(APPEND environment ";${no_leak_check}")
      string(APPEND content "set_tests_properties([=[${name}]=] PROPERTIES ENVIRONMENT [=[${environment}]=])\n")
    endif()
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
string(APPEND content "set_tests_properties([=[${name}]=] PROPERTIES SKIP_RETURN_CODE 77 LABELS window TIMEOUT ${timeout} "
                      "ENVIRONMENT [=[${no_leak_check}]=])\n")
file(WRITE ${OUT} "${content}")
