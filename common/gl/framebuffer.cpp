#include "gl/framebuffer.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
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
// WebGL 2 cannot glReadPixels the stencil or the depth. Both are drawn into a scratch RGBA8
// colour buffer by a full-screen triangle instead, and that is read:
// - the stencil one bit plane at a time: the framebuffer's depth/stencil attachment is attached to
//   the scratch framebuffer, and the triangle drawn with the stencil test (GL_EQUAL, bit, bit)
//   writes 255 into one channel where the bit is set: bits 0-3 into R, G, B, A, then bits 4-7;
// - the depth sampled from a depth texture (the attachment itself, or a renderbuffer's depth
//   blitted into one of its format), each float's 32 bits written as four bytes.
// Exact: no arithmetic touches a value. Every GL state this changes is put back.
#undef glReadPixels  // this file reads colour with WebGL's own (gl_web.h)
namespace {

GLuint scratchProgram(const char* fragment) {
  const char* vs =
      "#version 300 es\nvoid main() { vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);"
      " gl_Position = vec4(2.0 * p - 1.0, 0.0, 1.0); }\n";
  const auto stage = [](GLenum type, const char* text) {
    GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    return shader;
  };
  GLuint v = stage(GL_VERTEX_SHADER, vs), f = stage(GL_FRAGMENT_SHADER, fragment);
  GLuint program = glCreateProgram();
  glAttachShader(program, v);
  glAttachShader(program, f);
  glLinkProgram(program);
  glDeleteShader(v);
  glDeleteShader(f);
  return program;
}

struct Scratch {
  GLuint stencilProgram = 0, depthProgram = 0, vao = 0, fbo = 0, colour = 0, sampler = 0;
  int width = 0, height = 0;
  GLuint depthFbo = 0, depthTexture = 0;  // a renderbuffer's depth, blitted to be sampled
  GLenum depthFormat = GL_NONE;
  int depthWidth = 0, depthHeight = 0;
};

Scratch& scratch() {
  static Scratch s;
  if (!s.stencilProgram) {
    s.stencilProgram =
        scratchProgram("#version 300 es\nprecision highp float; out vec4 c; void main() { c = vec4(1.0); }\n");
    s.depthProgram = scratchProgram(
        "#version 300 es\nprecision highp float; uniform highp sampler2D depth; out vec4 c;\n"
        "void main() { uint d = floatBitsToUint(texelFetch(depth, ivec2(gl_FragCoord.xy), 0).r);\n"
        " c = vec4(uvec4(d, d >> 8, d >> 16, d >> 24) & 255u) / 255.0; }\n");
    glGenVertexArrays(1, &s.vao);
    glGenFramebuffers(1, &s.fbo);
    glGenRenderbuffers(1, &s.colour);
    glGenFramebuffers(1, &s.depthFbo);
    glGenSamplers(1, &s.sampler);  // texelFetch of a depth texture: no filtering, no comparison
    glSamplerParameteri(s.sampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(s.sampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(s.sampler, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  }
  return s;
}

// The GL state the scratch draws change, saved on construction and put back on destruction.
class SavedState {
 public:
  SavedState() {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFbo_);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFbo_);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao_);
    glGetIntegerv(GL_RENDERBUFFER_BINDING, &renderbuffer_);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture_);
    glGetIntegerv(GL_SAMPLER_BINDING, &sampler_);
    glGetIntegerv(GL_VIEWPORT, viewport_);
    glGetIntegerv(GL_STENCIL_FUNC, &func_[0]);
    glGetIntegerv(GL_STENCIL_REF, &ref_[0]);
    glGetIntegerv(GL_STENCIL_VALUE_MASK, &valueMask_[0]);
    glGetIntegerv(GL_STENCIL_WRITEMASK, &writeMask_[0]);
    glGetIntegerv(GL_STENCIL_FAIL, &sfail_[0]);
    glGetIntegerv(GL_STENCIL_PASS_DEPTH_FAIL, &dpfail_[0]);
    glGetIntegerv(GL_STENCIL_PASS_DEPTH_PASS, &dppass_[0]);
    glGetIntegerv(GL_STENCIL_BACK_FUNC, &func_[1]);
    glGetIntegerv(GL_STENCIL_BACK_REF, &ref_[1]);
    glGetIntegerv(GL_STENCIL_BACK_VALUE_MASK, &valueMask_[1]);
    glGetIntegerv(GL_STENCIL_BACK_WRITEMASK, &writeMask_[1]);
    glGetIntegerv(GL_STENCIL_BACK_FAIL, &sfail_[1]);
    glGetIntegerv(GL_STENCIL_BACK_PASS_DEPTH_FAIL, &dpfail_[1]);
    glGetIntegerv(GL_STENCIL_BACK_PASS_DEPTH_PASS, &dppass_[1]);
    glGetBooleanv(GL_COLOR_WRITEMASK, colourMask_);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clearColour_);
    for (std::size_t i = 0; i < std::size(kCaps); ++i) enabled_[i] = glIsEnabled(kCaps[i]);
    for (GLenum cap : kCaps) glDisable(cap);
  }
  ~SavedState() {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFbo_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFbo_));
    glUseProgram(static_cast<GLuint>(program_));
    glBindVertexArray(static_cast<GLuint>(vao_));
    glBindRenderbuffer(GL_RENDERBUFFER, static_cast<GLuint>(renderbuffer_));
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture_));
    glBindSampler(0, static_cast<GLuint>(sampler_));
    glActiveTexture(static_cast<GLenum>(activeTexture_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    const GLenum faces[2] = {GL_FRONT, GL_BACK};
    for (int i = 0; i < 2; ++i) {
      glStencilFuncSeparate(faces[i], static_cast<GLenum>(func_[i]), ref_[i], static_cast<GLuint>(valueMask_[i]));
      glStencilMaskSeparate(faces[i], static_cast<GLuint>(writeMask_[i]));
      glStencilOpSeparate(faces[i], static_cast<GLenum>(sfail_[i]), static_cast<GLenum>(dpfail_[i]),
                          static_cast<GLenum>(dppass_[i]));
    }
    glColorMask(colourMask_[0], colourMask_[1], colourMask_[2], colourMask_[3]);
    glDepthMask(depthMask_);
    glClearColor(clearColour_[0], clearColour_[1], clearColour_[2], clearColour_[3]);
    for (std::size_t i = 0; i < std::size(kCaps); ++i) {
      if (enabled_[i])
        glEnable(kCaps[i]);
      else
        glDisable(kCaps[i]);
    }
  }
  SavedState(const SavedState&) = delete;
  SavedState& operator=(const SavedState&) = delete;

 private:
  static constexpr GLenum kCaps[] = {GL_STENCIL_TEST, GL_DEPTH_TEST, GL_BLEND, GL_CULL_FACE, GL_SCISSOR_TEST,
                                     GL_RASTERIZER_DISCARD, GL_POLYGON_OFFSET_FILL};
  GLint drawFbo_ = 0, readFbo_ = 0, program_ = 0, vao_ = 0, renderbuffer_ = 0, activeTexture_ = 0, texture_ = 0,
        sampler_ = 0, viewport_[4] = {};
  GLint func_[2] = {}, ref_[2] = {}, valueMask_[2] = {}, writeMask_[2] = {}, sfail_[2] = {}, dpfail_[2] = {},
        dppass_[2] = {};
  GLboolean colourMask_[4] = {}, depthMask_ = GL_TRUE, enabled_[std::size(kCaps)] = {};
  GLfloat clearColour_[4] = {};
};

struct Attached {
  GLint type = GL_NONE, name = 0;
};

// What `framebuffer` has at `attachment` (bound for reading here).
Attached attachedAt(GLuint framebuffer, GLenum attachment) {
  Attached a;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
                                        &a.type);
  if (a.type != GL_NONE)
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
                                          &a.name);
  return a;
}

void attach(GLenum attachment, const Attached& a) {
  if (a.type == GL_TEXTURE)
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, attachment, GL_TEXTURE_2D, static_cast<GLuint>(a.name), 0);
  else
    glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, attachment, GL_RENDERBUFFER,
                              a.type == GL_RENDERBUFFER ? static_cast<GLuint>(a.name) : 0);
}

// Binds the scratch framebuffer for drawing, its colour buffer width x height, the viewport on it.
void bindScratch(Scratch& s, int width, int height) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, s.fbo);
  if (s.width != width || s.height != height) {
    glBindRenderbuffer(GL_RENDERBUFFER, s.colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    s.width = width;
    s.height = height;
  }
  glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, s.colour);
  glViewport(0, 0, width, height);
  glBindVertexArray(s.vao);
}

void readScratch(Scratch& s, std::vector<std::uint8_t>& rgba) {
  rgba.resize(static_cast<std::size_t>(s.width) * static_cast<std::size_t>(s.height) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, s.fbo);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, s.width, s.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
}

// The stencil, one byte a pixel, bottom row first (glReadPixels' order).
std::vector<std::uint8_t> stencilRows(GLuint framebuffer, int width, int height) {
  Scratch& s = scratch();
  SavedState saved;
  Attached stencil = attachedAt(framebuffer, GL_STENCIL_ATTACHMENT);
  if (stencil.type == GL_NONE) throw UsageError("the framebuffer to read has no stencil");
  const bool packed = stencil.type == attachedAt(framebuffer, GL_DEPTH_ATTACHMENT).type &&
                      stencil.name == attachedAt(framebuffer, GL_DEPTH_ATTACHMENT).name;
  bindScratch(s, width, height);
  // WebGL 2 refuses a depth and a stencil attachment apart when they are one packed image.
  attach(packed ? GL_DEPTH_STENCIL_ATTACHMENT : GL_STENCIL_ATTACHMENT, stencil);
  glEnable(GL_STENCIL_TEST);
  glStencilMask(0);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glDepthMask(GL_FALSE);
  glUseProgram(s.stencilProgram);
  std::vector<std::uint8_t> rows(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0), rgba;
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
    readScratch(s, rgba);
    for (std::size_t i = 0; i < rows.size(); ++i)
      for (int channel = 0; channel < 4; ++channel)
        if (rgba[4 * i + channel] >= 128) rows[i] |= static_cast<std::uint8_t>(1u << (4 * half + channel));
  }
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, s.fbo);
  attach(packed ? GL_DEPTH_STENCIL_ATTACHMENT : GL_STENCIL_ATTACHMENT, {});
  return rows;
}

// The depth as window depths, bottom row first (glReadPixels' order).
std::vector<float> depthRows(GLuint framebuffer, int width, int height) {
  Scratch& s = scratch();
  SavedState saved;
  Attached depth = attachedAt(framebuffer, GL_DEPTH_ATTACHMENT);
  if (depth.type == GL_NONE) throw UsageError("the framebuffer to read has no depth");
  GLuint texture = static_cast<GLuint>(depth.name);
  if (depth.type == GL_RENDERBUFFER) {  // a renderbuffer cannot be sampled: blit it into a texture
    GLint format = GL_NONE;
    glBindRenderbuffer(GL_RENDERBUFFER, static_cast<GLuint>(depth.name));
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &format);
    if (!s.depthTexture || s.depthFormat != static_cast<GLenum>(format) || s.depthWidth != width ||
        s.depthHeight != height) {
      if (s.depthTexture) glDeleteTextures(1, &s.depthTexture);
      glGenTextures(1, &s.depthTexture);
      glBindTexture(GL_TEXTURE_2D, s.depthTexture);
      glTexStorage2D(GL_TEXTURE_2D, 1, static_cast<GLenum>(format), width, height);
      s.depthFormat = static_cast<GLenum>(format);
      s.depthWidth = width;
      s.depthHeight = height;
    }
    const bool packed = format == GL_DEPTH24_STENCIL8 || format == GL_DEPTH32F_STENCIL8;
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, s.depthFbo);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, packed ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                           GL_TEXTURE_2D, s.depthTexture, 0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    texture = s.depthTexture;
  }
  bindScratch(s, width, height);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_FALSE);
  glUseProgram(s.depthProgram);
  glBindTexture(GL_TEXTURE_2D, texture);
  glBindSampler(0, s.sampler);
  glUniform1i(glGetUniformLocation(s.depthProgram, "depth"), 0);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  std::vector<std::uint8_t> rgba;
  readScratch(s, rgba);
  std::vector<float> rows(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::uint32_t bits = rgba[4 * i] | rgba[4 * i + 1] << 8 | rgba[4 * i + 2] << 16 |
                               static_cast<std::uint32_t>(rgba[4 * i + 3]) << 24;
    std::memcpy(&rows[i], &bits, sizeof bits);
  }
  return rows;
}

// The size of what the read framebuffer holds: a renderbuffer attachment's, else the viewport's
// (WebGL 2 cannot ask a texture its size; the lessons read what they have just drawn).
std::pair<int, int> readFramebufferSize(GLuint framebuffer) {
  for (GLenum point : {GL_COLOR_ATTACHMENT0, GL_DEPTH_ATTACHMENT, GL_STENCIL_ATTACHMENT}) {
    const Attached a = attachedAt(framebuffer, point);
    if (a.type != GL_RENDERBUFFER) continue;
    GLint bound = 0, w = 0, h = 0;
    glGetIntegerv(GL_RENDERBUFFER_BINDING, &bound);
    glBindRenderbuffer(GL_RENDERBUFFER, static_cast<GLuint>(a.name));
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &w);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_HEIGHT, &h);
    glBindRenderbuffer(GL_RENDERBUFFER, static_cast<GLuint>(bound));
    return {w, h};
  }
  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);
  return {viewport[0] + viewport[2], viewport[1] + viewport[3]};
}

// Copies the rectangle x, y, w, h of rows (fullWidth wide, `bytes` a pixel) to `out`, each row
// padded to GL_PACK_ALIGNMENT as glReadPixels pads it.
void copyRectangle(const std::uint8_t* rows, int fullWidth, int bytes, GLint x, GLint y, GLsizei w, GLsizei h,
                   void* out) {
  GLint alignment = 4;
  glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
  const std::size_t row = static_cast<std::size_t>(w) * static_cast<std::size_t>(bytes);
  const std::size_t stride = (row + static_cast<std::size_t>(alignment) - 1) / static_cast<std::size_t>(alignment) *
                             static_cast<std::size_t>(alignment);
  for (GLsizei j = 0; j < h; ++j)
    std::memcpy(static_cast<std::uint8_t*>(out) + static_cast<std::size_t>(j) * stride,
                rows + (static_cast<std::size_t>(y + j) * static_cast<std::size_t>(fullWidth) +
                        static_cast<std::size_t>(x)) * static_cast<std::size_t>(bytes),
                row);
}

}  // namespace

void webReadPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type, void* pixels) {
  const bool stencil = format == GL_STENCIL_INDEX && type == GL_UNSIGNED_BYTE;
  const bool depth = format == GL_DEPTH_COMPONENT && type == GL_FLOAT;
  if (format == GL_RED_INTEGER && type == GL_UNSIGNED_INT) {
    // WebGL 2 always reads an unsigned integer buffer as RGBA_INTEGER (RED_INTEGER only where the
    // implementation says so): the red of each.
    std::vector<GLuint> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    glReadPixels(x, y, width, height, GL_RGBA_INTEGER, GL_UNSIGNED_INT, rgba.data());
    auto* red = static_cast<GLuint*>(pixels);
    for (std::size_t i = 0; i * 4 < rgba.size(); ++i) red[i] = rgba[i * 4];
    return;
  }
  if (!stencil && !depth) {
    glReadPixels(x, y, width, height, format, type, pixels);
    return;
  }
  GLint bound = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &bound);
  const GLuint framebuffer = static_cast<GLuint>(bound);
  const auto [fullWidth, fullHeight] = readFramebufferSize(framebuffer);
  if (x < 0 || y < 0 || x + width > fullWidth || y + height > fullHeight)
    throw UsageError("reading " + std::string(stencil ? "stencil" : "depth") + " outside the framebuffer");
  if (stencil) {
    const std::vector<std::uint8_t> rows = stencilRows(framebuffer, fullWidth, fullHeight);
    copyRectangle(rows.data(), fullWidth, 1, x, y, width, height, pixels);
  } else {
    const std::vector<float> rows = depthRows(framebuffer, fullWidth, fullHeight);
    copyRectangle(reinterpret_cast<const std::uint8_t*>(rows.data()), fullWidth, 4, x, y, width, height, pixels);
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
}

Image readStencilPixels(GLuint framebuffer, int width, int height) {
  Image image(width, height, 1);
  image.pixels = stencilRows(framebuffer, width, height);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);  // as the desktop reader leaves it
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  flipRows(image);
  return image;
}

std::vector<float> readDepthPixels(GLuint framebuffer, int width, int height) {
  std::vector<float> depth = depthRows(framebuffer, width, height);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  const auto row = static_cast<std::ptrdiff_t>(width);
  for (int y = 0; y < height / 2; ++y)
    std::swap_ranges(depth.begin() + y * row, depth.begin() + (y + 1) * row, depth.end() - (y + 1) * row);
  return depth;
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

std::vector<std::uint64_t> stencilHistogram(GLuint framebuffer, glm::ivec2 size) {
  std::vector<std::uint64_t> histogram(256, 0);
  for (std::uint8_t value : readStencilPixels(framebuffer, size.x, size.y).pixels) ++histogram[value];
  return histogram;
}

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
