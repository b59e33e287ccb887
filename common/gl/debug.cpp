#include "gl/debug.h"

#include <vector>

#include "gl/errors.h"
#include "gl/gl.h"

namespace stencil {
namespace {

std::vector<std::string> debugErrors;

#ifndef __EMSCRIPTEN__
void GLAD_API_PTR onDebugMessage(GLenum, GLenum type, GLuint, GLenum, GLsizei, const GLchar* message,
                                 const void*) {
  if (type == GL_DEBUG_TYPE_ERROR) debugErrors.emplace_back(message);
}
#endif

const char* errorName(GLenum e) {
  switch (e) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "unknown GL error";
  }
}

}  // namespace

void enableDebugOutput(const GlFeatures& features) {
#ifdef __EMSCRIPTEN__
  (void)features;  // WebGL has no debug output: glGetError alone reports errors
#else
  if (!features.khrDebug || !glDebugMessageCallback) return;
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);  // so the error lands in the pass that caused it
  glDebugMessageCallback(onDebugMessage, nullptr);
#endif
}

void checkGlErrors(const std::string& where) {
  std::string report;
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError())
    report += std::string(report.empty() ? "" : ", ") + errorName(e);
  for (const auto& m : debugErrors) report += std::string(report.empty() ? "" : ", ") + m;
  debugErrors.clear();
  if (!report.empty()) throw GlError("GL error " + where + ": " + report);
}

}  // namespace stencil
