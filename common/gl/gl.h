// The one include for OpenGL: glad's generated loader (GL 3.3 core + the optional
// extensions the lessons detect at run time), or in the browser WebGL 2 through Emscripten
// (gl_web.h). Never include a system GL header.
#pragma once
#ifdef __EMSCRIPTEN__
#include "gl/gl_web.h"
#else
#include <glad/gl.h>
#endif
