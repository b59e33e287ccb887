// The off-screen framebuffer every lesson renders into: RGBA8 colour (half floats for a lesson's
// own accumulation target) plus a packed depth/stencil attachment (24-bit fixed-point depth, or
// 32-bit float depth for reversed depth).
// Its stencil bits are verified, never assumed from a pixel format, so every backend gives the
// same stencil buffer.
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "gl/gl.h"
#include "gl/image.h"

namespace stencil {

// Reads the colour of any framebuffer (0: the window's), RGBA, top row first, opaque.
Image readColourPixels(GLuint framebuffer, int width, int height);
// Reads a framebuffer's stencil, one byte per pixel, top row first.
Image readStencilPixels(GLuint framebuffer, int width, int height);
// Reads a framebuffer's depth as window depths in [0, 1] (any depth format), width x height
// floats, top row first.
std::vector<float> readDepthPixels(GLuint framebuffer, int width, int height);
// Pixels per stencil value (256 counts) of a framebuffer's stencil: what full-screen queries
// (GL_SAMPLES_PASSED under GL_EQUAL) count on the desktop, for the browser, whose queries are boolean.
std::vector<std::uint64_t> stencilHistogram(GLuint framebuffer, glm::ivec2 size);
// The readers bind `framebuffer` for reading and set GL_PACK_ALIGNMENT, and leave both so.

// The depth buffer's format. Fixed24: GL_DEPTH24_STENCIL8, steps of 2^-24 over [0, 1], every
// lesson's default. Float32: GL_DEPTH32F_STENCIL8 (core since 3.0), a float per pixel, whose
// steps shrink towards 0; worth it with reversed depth (geometry/projection.h).
enum class DepthFormat { Fixed24, Float32 };

// The packed depth/stencil internal format for a DepthFormat (for a lesson's own targets that
// blit depth and stencil to the framework's, which needs identical formats).
GLenum depthStencilFormat(DepthFormat);
const char* depthFormatName(DepthFormat);  // "fixed24", "float32"

// The colour buffer's format. RGBA8: 8 bits a channel, every lesson's default. RGBA16F: a half
// float a channel (core since 3.0), for a sum of many small terms (lights added one pass each)
// that 8 bits would round term by term; a copy into RGBA8 clamps it to 0..1.
enum class ColourFormat { RGBA8, RGBA16F };

class Framebuffer {
 public:
  // stencilBits is 8 for lessons; 0 builds one without stencil (to test the check). Throws
  // UsageError when GL calls the result incomplete.
  Framebuffer(int width, int height, int stencilBits = 8, DepthFormat = DepthFormat::Fixed24,
              ColourFormat = ColourFormat::RGBA8);
  ~Framebuffer();
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  void bind() const;  // binds for drawing and sets the viewport to the whole buffer
  int width() const { return width_; }
  int height() const { return height_; }
  GLuint id() const { return fbo_; }
  int stencilBits() const { return stencilBits_; }  // as queried from GL
  DepthFormat depthFormat() const { return depthFormat_; }
  ColourFormat colourFormat() const { return colourFormat_; }

  Image readColour() const;   // RGBA, top row first, alpha 255
  Image readStencil() const;  // one byte per pixel, top row first
  // The depth buffer as window depths in [0, 1] (either format), width x height, top row first.
  std::vector<float> readDepth() const;

 private:
  int width_, height_;
  int stencilBits_ = 0;
  DepthFormat depthFormat_;
  ColourFormat colourFormat_;
  GLuint fbo_ = 0, colour_ = 0, depthStencil_ = 0;
};

}  // namespace stencil
