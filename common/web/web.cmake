# The course in a browser (cmake --preset web): every lesson built by Emscripten for WebGL 2 from
# the same sources, as a page of the static site ${CMAKE_BINARY_DIR}/site: index.html (the
# course's contents) and NN-name.html with NN-name.js and NN-name.wasm, the lesson's docs page
# converted by pandoc beside the canvas. Any static web server serves the folder.
#
# Debian's packages (common/install-deps.sh --web): emscripten, node-acorn (its optimizer finds
# it through NODE_PATH=/usr/share/nodejs, which the preset sets), pandoc.

set(STENCIL_SITE ${CMAKE_BINARY_DIR}/site)
include(${PROJECT_SOURCE_DIR}/common/web/lessons.cmake)

find_program(PANDOC_EXECUTABLE pandoc REQUIRED)

# Each header-only library in a folder of its own: /usr/include itself on em++'s path would shadow
# Emscripten's C library with the host's.
set(web_include ${CMAKE_BINARY_DIR}/include)
foreach(link glm/glm:/usr/include/glm nlohmann/nlohmann:/usr/include/nlohmann
        tinyobj/tiny_obj_loader.h:/usr/include/tiny_obj_loader.h stb:/usr/include/stb)
  string(REPLACE ":" ";" pair ${link})
  list(GET pair 0 name)
  list(GET pair 1 target)
  if(NOT EXISTS ${target})
    message(FATAL_ERROR "${target} not found: common/install-deps.sh installs the headers the browser build uses")
  endif()
  get_filename_component(parent ${web_include}/${name} DIRECTORY)
  file(MAKE_DIRECTORY ${parent})
  if(NOT EXISTS ${web_include}/${name})
    file(CREATE_LINK ${target} ${web_include}/${name} SYMBOLIC)
  endif()
endforeach()
add_library(glm::glm INTERFACE IMPORTED)
target_include_directories(glm::glm SYSTEM INTERFACE ${web_include}/glm)
add_library(web_headers INTERFACE)
target_include_directories(web_headers SYSTEM INTERFACE ${web_include}/nlohmann ${web_include}/tinyobj ${web_include}/stb)
add_library(tinyobjloader::tinyobjloader ALIAS web_headers)

# C++ exceptions carry the lessons' errors (a bad setting is one line on the page), so catching
# is on; wasm SIMD stands for the SSE intrinsics of the dual-space silhouettes.
add_compile_options(-fexceptions -msimd128 -msse)
# Floating-point from_chars and to_chars, which Emscripten 3.1.6's libc++ lacks.
add_compile_options("SHELL:-include ${PROJECT_SOURCE_DIR}/common/web/charconv_float.h")
add_link_options(-fexceptions)

# wasm32's size_t is 32 bits: the geometry layer's 64-bit counts narrowed to sizes warn there, and
# are not yet audited for it (docs/web.md).
list(APPEND STENCIL_WARNINGS -Wno-shorten-64-to-32)

# The geometry layer as it is, and the GL glue without the desktop's backends and window.
add_subdirectory(common/geometry)
add_library(stencil_gl STATIC
    common/gl/context.cpp
    common/gl/context_web.cpp
    common/gl/debug.cpp
    common/gl/shader.cpp
    common/gl/gpu_mesh.cpp
    common/gl/doubled_caster.cpp
    common/gl/accumulation_target.cpp
    common/gl/scene_meshes.cpp
    common/gl/light_shading.cpp
    common/gl/light_marker.cpp
    common/gl/framebuffer.cpp
    common/gl/image.cpp
    common/gl/stencil_view.cpp
    common/gl/overlay.cpp
    common/gl/recorder.cpp
    common/gl/golden.cpp
    common/gl/lesson.cpp
    common/gl/session.cpp
    common/gl/options.cpp
    common/gl/web_run.cpp
    common/web/third_party.cpp)
target_include_directories(stencil_gl PUBLIC ${PROJECT_SOURCE_DIR}/common)
target_link_libraries(stencil_gl PUBLIC stencil_geometry glm::glm PRIVATE web_headers)
target_compile_options(stencil_gl PRIVATE ${STENCIL_WARNINGS})
set_source_files_properties(common/web/third_party.cpp PROPERTIES COMPILE_OPTIONS "-w")
# The shaders are packed into each lesson's program at /shaders (--embed-file below).
target_compile_definitions(stencil_gl PRIVATE STENCIL_SOURCE_DIR="/")

# A lesson's title: its docs page's first heading.
function(stencil_web_title id out)
  file(STRINGS ${PROJECT_SOURCE_DIR}/docs/${id}.md heading REGEX "^# " LIMIT_COUNT 1)
  string(REGEX REPLACE "^# +" "" heading "${heading}")
  set(${out} "${heading}" PARENT_SCOPE)
endfunction()

file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/pages)
set(page_template ${PROJECT_SOURCE_DIR}/common/web/lesson.html)
set(page_script ${PROJECT_SOURCE_DIR}/common/web/page.cmake)
set(links_filter ${PROJECT_SOURCE_DIR}/common/web/repository_links.lua)
set(window_filter ${PROJECT_SOURCE_DIR}/common/web/in_the_window.lua)
set(index_entries "")
list(LENGTH STENCIL_WEB_LESSONS count)
math(EXPR last "${count} - 1")
set(pages)
foreach(i RANGE ${last})
  list(GET STENCIL_WEB_LESSONS ${i} id)
  file(GLOB sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/lessons/${id}/*.cpp)
  add_executable(${id} ${sources})
  target_link_libraries(${id} PRIVATE stencil_gl)
  target_compile_options(${id} PRIVATE ${STENCIL_WARNINGS})
  set_target_properties(${id} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${STENCIL_SITE} SUFFIX .js)
  target_link_options(${id} PRIVATE
    -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2 -sALLOW_MEMORY_GROWTH=1 -sENVIRONMENT=web
    -sEXPORTED_RUNTIME_METHODS=ccall,FS
    "SHELL:--embed-file ${PROJECT_SOURCE_DIR}/shaders@/shaders")
  file(GLOB_RECURSE shader_files CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/shaders/*)
  set_property(TARGET ${id} APPEND PROPERTY LINK_DEPENDS ${shader_files})
  if(DEFINED STENCIL_WEB_SCENES_${id})
    set(scene_globs ${STENCIL_WEB_SCENES_${id}} meshes/*.obj)
    list(TRANSFORM scene_globs PREPEND ${PROJECT_SOURCE_DIR}/tests/scenes/)
    file(GLOB scene_files CONFIGURE_DEPENDS ${scene_globs})
    set(left_out ${STENCIL_WEB_SCENES_LEFT_OUT_${id}})
    list(TRANSFORM left_out PREPEND ${PROJECT_SOURCE_DIR}/tests/scenes/)
    list(REMOVE_ITEM scene_files ${left_out})
    foreach(file IN LISTS scene_files)
      file(RELATIVE_PATH name ${PROJECT_SOURCE_DIR}/tests/scenes ${file})
      target_link_options(${id} PRIVATE "SHELL:--embed-file ${file}@/scenes/${name}")
    endforeach()
    set_property(TARGET ${id} APPEND PROPERTY LINK_DEPENDS ${scene_files})
  endif()

  stencil_web_title(${id} title)
  set(previous "")
  set(next "")
  set(previous_title "")
  set(next_title "")
  if(i GREATER 0)
    math(EXPR j "${i} - 1")
    list(GET STENCIL_WEB_LESSONS ${j} previous)
    stencil_web_title(${previous} previous_title)
  endif()
  if(i LESS last)
    math(EXPR j "${i} + 1")
    list(GET STENCIL_WEB_LESSONS ${j} next)
    stencil_web_title(${next} next_title)
  endif()
  # The docs page, converted at build time (its links to the repository's files made plain text by
  # repository_links.lua; a line under "In the window" saying the page's controls do what the keys
  # do, in_the_window.lua), then set in the page beside the canvas.
  set(fragment ${CMAKE_BINARY_DIR}/pages/${id}.fragment.html)
  set(page ${STENCIL_SITE}/${id}.html)
  set(figures_stamp ${CMAKE_BINARY_DIR}/pages/${id}.figures.stamp)
  add_custom_command(OUTPUT ${page}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/pages
    COMMAND ${PANDOC_EXECUTABLE} --from gfm --to html5 --lua-filter ${links_filter} --lua-filter ${window_filter}
      --output ${fragment}
      ${PROJECT_SOURCE_DIR}/docs/${id}.md
    COMMAND ${CMAKE_COMMAND} -DTEMPLATE=${page_template} -DFRAGMENT=${fragment} -DOUT=${page}
      -DID=${id} "-DTITLE=${title}" -DPREVIOUS=${previous} -DNEXT=${next} "-DPREVIOUS_TITLE=${previous_title}"
      "-DNEXT_TITLE=${next_title}" -P ${page_script}
    DEPENDS ${PROJECT_SOURCE_DIR}/docs/${id}.md ${page_template} ${page_script} ${links_filter} ${window_filter}
    COMMENT "Page ${id}.html (pandoc)"
    VERBATIM)
  # The pictures the page shows (figures/..., sweeps/...), each copied to the same place in the
  # site; read from the page again whenever it changes.
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/docs/${id}.md)
  file(READ ${PROJECT_SOURCE_DIR}/docs/${id}.md markdown)
  string(REGEX MATCHALL "!\\[[^]]*\\]\\([^) ]+" images "${markdown}")
  set(figures)
  foreach(image IN LISTS images)
    string(REGEX REPLACE "^!\\[[^]]*\\]\\(" "" image "${image}")
    if(NOT image MATCHES "^[a-z]+:" AND EXISTS ${PROJECT_SOURCE_DIR}/docs/${image})
      list(APPEND figures ${image})
    endif()
  endforeach()
  list(REMOVE_DUPLICATES figures)
  set(copies)
  foreach(image IN LISTS figures)
    list(APPEND copies COMMAND ${CMAKE_COMMAND} -E copy_if_different ${PROJECT_SOURCE_DIR}/docs/${image}
         ${STENCIL_SITE}/${image})
  endforeach()
  if(figures)
    list(TRANSFORM figures PREPEND ${PROJECT_SOURCE_DIR}/docs/ OUTPUT_VARIABLE figure_files)
    add_custom_command(OUTPUT ${figures_stamp}
      ${copies}
      COMMAND ${CMAKE_COMMAND} -E touch ${figures_stamp}
      DEPENDS ${figure_files}
      VERBATIM)
    list(APPEND pages ${figures_stamp})
  endif()
  list(APPEND pages ${page})
  string(APPEND index_entries "      <li><a href=\"${id}.html\">${title}</a></li>\n")
endforeach()

# The course's contents, and the page's script and style.
configure_file(${PROJECT_SOURCE_DIR}/common/web/index.html ${STENCIL_SITE}/index.html @ONLY)
add_custom_command(OUTPUT ${STENCIL_SITE}/lesson.js ${STENCIL_SITE}/course.css
  COMMAND ${CMAKE_COMMAND} -E copy ${PROJECT_SOURCE_DIR}/common/web/lesson.js ${STENCIL_SITE}/lesson.js
  COMMAND ${CMAKE_COMMAND} -E copy ${PROJECT_SOURCE_DIR}/common/web/course.css ${STENCIL_SITE}/course.css
  DEPENDS ${PROJECT_SOURCE_DIR}/common/web/lesson.js ${PROJECT_SOURCE_DIR}/common/web/course.css
  VERBATIM)
add_custom_target(site ALL DEPENDS ${pages} ${STENCIL_SITE}/lesson.js ${STENCIL_SITE}/course.css)
