// GL errors never pass silently: glGetError and KHR_debug error messages are turned into
// a GlError naming where they happened.
#pragma once
#include <string>

#include "gl/context.h"

namespace stencil {

// Routes KHR_debug messages of type error into the check below (no-op without KHR_debug).
void enableDebugOutput(const GlFeatures&);
// Throws GlError if glGetError or debug output reported anything since the last check.
void checkGlErrors(const std::string& where);

}  // namespace stencil
