// The one include for OpenGL: glad's generated loader (GL 3.3 core + the optional
// extensions the lessons detect at run time). Never include a system GL header.
#pragma once
#include <glad/gl.h>
