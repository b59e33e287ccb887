// WebGL 2 as a GL 3.3 core subset (the browser build, Emscripten). WebGL 2 is OpenGL ES 3.0:
// the names below are GL 3.3's that ES lacks. Where a WebGL extension gives the same thing the
// name carries the extension's value (the same as desktop GL's), and the lessons use it only when
// Context::features() says the extension is there, as they do on the desktop. The rest are
// entry points the framework calls only behind a feature it never reports in the browser.
#pragma once
#include <GLES3/gl3.h>

// EXT_depth_clamp
#define GL_DEPTH_CLAMP 0x864F
// EXT_clip_control
#define GL_LOWER_LEFT 0x8CA1
#define GL_NEGATIVE_ONE_TO_ONE 0x935E
#define GL_ZERO_TO_ONE 0x935F
// WEBGL_clip_cull_distance
#define GL_CLIP_DISTANCE0 0x3000
#define GL_CLIP_DISTANCE1 0x3001
// EXT_disjoint_timer_query_webgl2
#define GL_TIME_ELAPSED 0x88BF
#define GL_QUERY_COUNTER_BITS 0x8864
// WebGL 2's occlusion queries are boolean: a query the lessons begin as GL_SAMPLES_PASSED says
// whether any sample passed (1) or none (0), which is all that lesson 14's layer bisection and
// early stop ask of it. A count taken from it feeds --stats only, which the browser does not have;
// lesson 13's histogram, which its picture needs, is read from the stencil there instead.
// (GlFeatures::samplesPassed is false in the browser: the pass recorder counts no samples.)
#define GL_SAMPLES_PASSED GL_ANY_SAMPLES_PASSED
// Desktop only: no statistics, depth bounds or debug output in WebGL 2.
#define GL_PRIMITIVES_SUBMITTED_ARB 0x82EF
#define GL_FRAGMENT_SHADER_INVOCATIONS_ARB 0x82F4
#define GL_DEPTH_BOUNDS_TEST_EXT 0x8890
#define GL_STENCIL_INDEX 0x1901
#define GL_DEBUG_OUTPUT 0x92E0
#define GL_DEBUG_OUTPUT_SYNCHRONOUS 0x8242
#define GL_DEBUG_TYPE_ERROR 0x824C

inline void glClearDepth(double depth) { glClearDepthf(static_cast<GLfloat>(depth)); }
inline void glDepthRange(double nearValue, double farValue) {
  glDepthRangef(static_cast<GLfloat>(nearValue), static_cast<GLfloat>(farValue));
}
// WebGL sizes points in the vertex shader only (gl_PointSize).
inline void glPointSize(GLfloat) {}
// Query results fit 32 bits in WebGL 2 (GL_ANY_SAMPLES_PASSED, or EXT_disjoint_timer_query's
// nanoseconds up to about 4 s).
inline void glGetQueryObjectui64v(GLuint query, GLenum name, GLuint64* value) {
  GLuint result = 0;
  glGetQueryObjectuiv(query, name, &result);
  *value = result;
}
// A texture made without pixels: the desktop ignores the type then, ES 3.0 requires the one its
// internal format takes (lesson 10 makes its RGBA8 and float targets alike, with GL_FLOAT).
inline void webTexImage2D(GLenum target, GLint level, GLint internalFormat, GLsizei width, GLsizei height,
                          GLint border, GLenum format, GLenum type, const void* pixels) {
  if (!pixels && internalFormat == GL_RGBA8) type = GL_UNSIGNED_BYTE;
  glTexImage2D(target, level, internalFormat, width, height, border, format, type, pixels);
}
#define glTexImage2D webTexImage2D
// glReadPixels of GL_STENCIL_INDEX or GL_DEPTH_COMPONENT (GL_UNSIGNED_BYTE, GL_FLOAT), which
// WebGL 2 refuses, read by drawing them into a colour buffer (common/gl/framebuffer.cpp);
// GL_RED_INTEGER (GL_UNSIGNED_INT) read as GL_RGBA_INTEGER, the one WebGL 2 always takes; any
// other format is WebGL's own glReadPixels.
namespace stencil {
void webReadPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type, void* pixels);
}
#define glReadPixels stencil::webReadPixels
// WEBGL_clip_cull_distance, where the browser has it (context_web.cpp). Without it, a shader's
// gl_ClipDistance becomes a discard in its fragment shader (glslForWebGl, common/gl/shader.h) and
// glEnable or glDisable of GL_CLIP_DISTANCEi does nothing; every other capability is WebGL's.
namespace stencil {
bool webClipDistance();
void webEnable(GLenum cap);
void webDisable(GLenum cap);
}
#define glEnable stencil::webEnable
#define glDisable stencil::webDisable
// EXT_clip_control's clipControlEXT, called where GlFeatures::clipControl says it is there
// (context_web.cpp).
void glClipControl(GLenum origin, GLenum depth);
// Never reported in the browser (GlFeatures::depthBoundsTest is false); a no-op for the linker.
inline void glDepthBoundsEXT(double, double) {}
