# The scene files a scene lesson's page offers (common/web/lessons.cmake: STENCIL_WEB_SCENES_<id>
# less STENCIL_WEB_SCENES_LEFT_OUT_<id>) must each be drawn by the native lesson (exit 0): a list
# entry the lesson refuses is a dead end for a reader. One frame each, 64x48.
# cmake -DEXE=lesson -DSCENES=tests/scenes "-DGLOBS=a;b" "-DLEFT_OUT=c;d" -DOUT=dir -P scene_lists.cmake
list(TRANSFORM GLOBS PREPEND ${SCENES}/)
file(GLOB files ${GLOBS})
list(TRANSFORM LEFT_OUT PREPEND ${SCENES}/)
list(REMOVE_ITEM files ${LEFT_OUT})
file(MAKE_DIRECTORY ${OUT})
set(refused "")
list(LENGTH files count)
foreach(file IN LISTS files)
  execute_process(COMMAND ${EXE} --headless --quiet --size 64x48 --scene ${file} --out ${OUT}/frame.png
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(rc EQUAL 77)
    message("no GL context: skipped")
    return()
  endif()
  if(NOT rc EQUAL 0)
    string(STRIP "${err}" err)
    string(APPEND refused "\n  ${err}")
  endif()
endforeach()
if(refused)
  message(FATAL_ERROR "the page offers scene files the lesson refuses (leave them out in common/web/lessons.cmake):${refused}")
endif()
message("${count} scene files offered, each drawn")
