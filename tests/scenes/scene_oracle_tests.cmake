# add_scene_oracle_tests(LESSON_TARGET [VARIANT NAME] files... [FAILS files...] [SIZES WxH...]): for
# each scene file (relative to tests/scenes/) and each size (default GOLDEN_SIZE), a test that runs
# the lesson (in that variant, else its first) on it and checks every light's shadow mask against a
# CPU ray cast (scene_oracle, tests/scenes/scene_oracle.cpp) at GOLDEN_TIME. Tests are named
# scene-oracle.LESSON_TARGET[.VARIANT].FILE, with .WxH after sizes other than GOLDEN_SIZE. Files
# after FAILS show an artifact of the lesson: their test passes only when the ray cast disagrees
# (scene_oracle --expect-failure). Included from the top level so lessons/ can call it.
function(add_scene_oracle_tests target)
  cmake_parse_arguments(ARG "" "VARIANT" "FAILS;SIZES" ${ARGN})
  set(prefix scene-oracle.${target})
  set(variant)
  if(ARG_VARIANT)
    set(prefix ${prefix}.${ARG_VARIANT})
    set(variant --variant ${ARG_VARIANT})
  endif()
  if(NOT ARG_SIZES)
    set(ARG_SIZES ${GOLDEN_SIZE})
  endif()
  foreach(size IN LISTS ARG_SIZES)
    foreach(file IN LISTS ARG_UNPARSED_ARGUMENTS ARG_FAILS)
      string(REGEX REPLACE "\\.scene$" "" name "${file}")
      string(REPLACE "/" "." name "${name}")
      if(NOT size STREQUAL GOLDEN_SIZE)
        set(name ${name}.${size})
      endif()
      set(expect)
      if(file IN_LIST ARG_FAILS)
        set(expect --expect-failure)
      endif()
      add_test(NAME ${prefix}.${name}
        COMMAND scene_oracle ${expect} ${variant} $<TARGET_FILE:${target}> ${PROJECT_SOURCE_DIR}/tests/scenes/${file}
                ${size} ${GOLDEN_TIME})
      set_tests_properties(${prefix}.${name} PROPERTIES LABELS oracle SKIP_RETURN_CODE 77 TIMEOUT 120)
    endforeach()
  endforeach()
endfunction()
