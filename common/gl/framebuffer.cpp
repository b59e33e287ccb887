#include "gl/framebuffer.h"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <string>

#include "gl/errors.h"

namespace stencil {
namespace {

// glReadPixels returns the bottom row first; images are stored top row first.
void flipRows(Image& image) {
  const size_t row = static_cast<size_t>(image.width) * image.channels;
  for (int y = 0; y < image.height / 2; ++y)
    std::swap_ranges(image.at(0, y), image.at(0, y) + row, image.at(0, image.height - 1 - y));
}

}  // namespace

GLenum depthStencilFormat(DepthFormat format) {
  return format == DepthFormat::Float32 ? GL_DEPTH32F_STENCIL8 : GL_DEPTH24_STENCIL8;
}

const char* depthFormatName(DepthFormat format) {
  return format == DepthFormat::Float32 ? "float32" : "fixed24";
}

Framebuffer::Framebuffer(int width, int height, int stencilBits, DepthFormat depthFormat,
                         ColourFormat colourFormat)
    : width_(width), height_(height), depthFormat_(depthFormat), colourFormat_(colourFormat) {
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glGenRenderbuffers(1, &colour_);
  glBindRenderbuffer(GL_RENDERBUFFER, colour_);
  glRenderbufferStorage(GL_RENDERBUFFER, colourFormat == ColourFormat::RGBA16F ? GL_RGBA16F : GL_RGBA8, width,
                        height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
  glGenRenderbuffers(1, &depthStencil_);
  glBindRenderbuffer(GL_RENDERBUFFER, depthStencil_);
  if (stencilBits > 0) {
    glRenderbufferStorage(GL_RENDERBUFFER, depthStencilFormat(depthFormat), width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depthStencil_);
  } else {
    glRenderbufferStorage(GL_RENDERBUFFER,
                          depthFormat == DepthFormat::Float32 ? GL_DEPTH_COMPONENT32F : GL_DEPTH_COMPONENT24,
                          width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depthStencil_);
  }
  GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw UsageError("framebuffer " + std::to_string(width) + "x" + std::to_string(height) +
                     " is incomplete (status " + std::to_string(status) + ")");

  // Ask GL what it actually gave us.
  GLint type = GL_NONE;
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT,
                                        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  if (type != GL_NONE)
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT,
                                          GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &stencilBits_);
}

Framebuffer::~Framebuffer() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &colour_);
  glDeleteRenderbuffers(1, &depthStencil_);
}

void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width_, height_);
}

Image readColourPixels(GLuint framebuffer, int width, int height) {
  Image image(width, height, 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
  flipRows(image);
  // Pictures show what a screen shows, and a screen does not show alpha: blending leaves
  // destination alpha below 1, which image viewers would composite over their background.
  for (size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 255;
  return image;
}

#ifdef __EMSCRIPTEN__
// WebGL 2 cannot glReadPixels the stencil. It is read one bit plane at a time instead: the
// framebuffer's depth/stencil attachment is attached to a scratch framebuffer with a colour buffer
// of its own, and a full-screen triangle drawn with the stencil test (GL_EQUAL, bit, bit) writes
// 255 into one channel where the bit is set: bits 0-3 into R, G, B, A, then bits 4-7. Exact: no
// arithmetic touches a value. Every GL state this changes is put back.
Image readStencilPixels(GLuint framebuffer, int width, int height) {
  struct Scratch {
    GLuint program = 0, vao = 0, fbo = 0, colour = 0;
    int width = 0, height = 0;
  };
  static Scratch scratch;
  if (!scratch.program) {
    const char* vs =
        "#version 300 es\nvoid main() { vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);"
        " gl_Position = vec4(2.0 * p - 1.0, 0.0, 1.0); }\n";
    const char* fs = "#version 300 es\nprecision highp float; out vec4 c; void main() { c = vec4(1.0); }\n";
    const auto stage = [](GLenum type, const char* text) {
      GLuint shader = glCreateShader(type);
      glShaderSource(shader, 1, &text, nullptr);
      glCompileShader(shader);
      return shader;
    };
    GLuint v = stage(GL_VERTEX_SHADER, vs), f = stage(GL_FRAGMENT_SHADER, fs);
    scratch.program = glCreateProgram();
    glAttachShader(scratch.program, v);
    glAttachShader(scratch.program, f);
    glLinkProgram(scratch.program);
    glDeleteShader(v);
    glDeleteShader(f);
    glGenVertexArrays(1, &scratch.vao);
    glGenFramebuffers(1, &scratch.fbo);
    glGenRenderbuffers(1, &scratch.colour);
  }
  // What the caller had.
  GLint drawFbo = 0, readFbo = 0, program = 0, vao = 0, renderbuffer = 0, viewport[4] = {};
  GLint stencilFunc = 0, stencilRef = 0, stencilValueMask = 0, stencilWriteMask = 0;
  GLint backFunc = 0, backRef = 0, backValueMask = 0, backWriteMask = 0;
  GLint sfail = 0, dpfail = 0, dppass = 0, backSfail = 0, backDpfail = 0, backDppass = 0;
  GLboolean colourMask[4] = {}, depthMask = GL_TRUE;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFbo);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFbo);
  glGetIntegerv(GL_CURRENT_PROGRAM, &program);
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao);
  glGetIntegerv(GL_RENDERBUFFER_BINDING, &renderbuffer);
  glGetIntegerv(GL_VIEWPORT, viewport);
  glGetIntegerv(GL_STENCIL_FUNC, &stencilFunc);
  glGetIntegerv(GL_STENCIL_REF, &stencilRef);
  glGetIntegerv(GL_STENCIL_VALUE_MASK, &stencilValueMask);
  glGetIntegerv(GL_STENCIL_WRITEMASK, &stencilWriteMask);
  glGetIntegerv(GL_STENCIL_BACK_FUNC, &backFunc);
  glGetIntegerv(GL_STENCIL_BACK_REF, &backRef);
  glGetIntegerv(GL_STENCIL_BACK_VALUE_MASK, &backValueMask);
  glGetIntegerv(GL_STENCIL_BACK_WRITEMASK, &backWriteMask);
  glGetIntegerv(GL_STENCIL_FAIL, &sfail);
  glGetIntegerv(GL_STENCIL_PASS_DEPTH_FAIL, &dpfail);
  glGetIntegerv(GL_STENCIL_PASS_DEPTH_PASS, &dppass);
  glGetIntegerv(GL_STENCIL_BACK_FAIL, &backSfail);
  glGetIntegerv(GL_STENCIL_BACK_PASS_DEPTH_FAIL, &backDpfail);
  glGetIntegerv(GL_STENCIL_BACK_PASS_DEPTH_PASS, &backDppass);
  glGetBooleanv(GL_COLOR_WRITEMASK, colourMask);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
  GLfloat clearColour[4] = {};
  glGetFloatv(GL_COLOR_CLEAR_VALUE, clearColour);
  const GLenum caps[] = {GL_STENCIL_TEST, GL_DEPTH_TEST, GL_BLEND, GL_CULL_FACE, GL_SCISSOR_TEST,
                         GL_RASTERIZER_DISCARD, GL_POLYGON_OFFSET_FILL};
  GLboolean enabled[std::size(caps)];
  for (std::size_t i = 0; i < std::size(caps); ++i) enabled[i] = glIsEnabled(caps[i]);

  // The framebuffer's depth/stencil renderbuffer, on the scratch framebuffer.
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  GLint type = GL_NONE, name = 0;
  glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_STENCIL_ATTACHMENT,
                                        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_STENCIL_ATTACHMENT,
                                        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
  if (type != GL_RENDERBUFFER) throw UsageError("the stencil to read is not a renderbuffer");
  glBindFramebuffer(GL_FRAMEBUFFER, scratch.fbo);
  if (scratch.width != width || scratch.height != height) {
    glBindRenderbuffer(GL_RENDERBUFFER, scratch.colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    scratch.width = width;
    scratch.height = height;
  }
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, scratch.colour);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, static_cast<GLuint>(name));
  glViewport(0, 0, width, height);
  for (GLenum cap : caps) glDisable(cap);
  glEnable(GL_STENCIL_TEST);
  glStencilMask(0);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glDepthMask(GL_FALSE);
  glUseProgram(scratch.program);
  glBindVertexArray(scratch.vao);
  Image image(width, height, 1);
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
  for (int half = 0; half < 2; ++half) {
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    for (int channel = 0; channel < 4; ++channel) {
      const GLuint bit = 1u << (4 * half + channel);
      glColorMask(channel == 0, channel == 1, channel == 2, channel == 3);
      glStencilFunc(GL_EQUAL, static_cast<GLint>(bit), bit);
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
      for (int channel = 0; channel < 4; ++channel)
        if (rgba[4 * i + channel] >= 128) image.pixels[i] |= static_cast<std::uint8_t>(1u << (4 * half + channel));
  }
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);

  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFbo));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);  // as the desktop reader leaves it
  glUseProgram(static_cast<GLuint>(program));
  glBindVertexArray(static_cast<GLuint>(vao));
  glBindRenderbuffer(GL_RENDERBUFFER, static_cast<GLuint>(renderbuffer));
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  glStencilFuncSeparate(GL_FRONT, static_cast<GLenum>(stencilFunc), stencilRef, static_cast<GLuint>(stencilValueMask));
  glStencilFuncSeparate(GL_BACK, static_cast<GLenum>(backFunc), backRef, static_cast<GLuint>(backValueMask));
  glStencilMaskSeparate(GL_FRONT, static_cast<GLuint>(stencilWriteMask));
  glStencilMaskSeparate(GL_BACK, static_cast<GLuint>(backWriteMask));
  glStencilOpSeparate(GL_FRONT, static_cast<GLenum>(sfail), static_cast<GLenum>(dpfail), static_cast<GLenum>(dppass));
  glStencilOpSeparate(GL_BACK, static_cast<GLenum>(backSfail), static_cast<GLenum>(backDpfail),
                      static_cast<GLenum>(backDppass));
  glColorMask(colourMask[0], colourMask[1], colourMask[2], colourMask[3]);
  glDepthMask(depthMask);
  glClearColor(clearColour[0], clearColour[1], clearColour[2], clearColour[3]);
  for (std::size_t i = 0; i < std::size(caps); ++i) {
    if (enabled[i])
      glEnable(caps[i]);
    else
      glDisable(caps[i]);
  }
  flipRows(image);
  return image;
}

std::vector<float> readDepthPixels(GLuint, int, int) {
  throw UsageError("reading the depth buffer is not in the browser build yet (WebGL 2 cannot glReadPixels depth)");
}
#else
Image readStencilPixels(GLuint framebuffer, int width, int height) {
  Image image(width, height, 1);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, image.pixels.data());
  flipRows(image);
  return image;
}

std::vector<float> readDepthPixels(GLuint framebuffer, int width, int height) {
  std::vector<float> depth(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  const auto row = static_cast<std::ptrdiff_t>(width);
  for (int y = 0; y < height / 2; ++y)
    std::swap_ranges(depth.begin() + y * row, depth.begin() + (y + 1) * row, depth.end() - (y + 1) * row);
  return depth;
}
#endif

Image Framebuffer::readColour() const {
  return readColourPixels(fbo_, width_, height_);
}

Image Framebuffer::readStencil() const {
  return readStencilPixels(fbo_, width_, height_);
}

std::vector<float> Framebuffer::readDepth() const {
  return readDepthPixels(fbo_, width_, height_);
}

}  // namespace stencil
