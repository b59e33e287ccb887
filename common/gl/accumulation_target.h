// A lesson's own framebuffer for a sum of passes (lesson 16 adds each light's illumination into
// it, McGuire et al.'s rendering system): its colour in half floats, so that many dim lights are
// not rounded to 1/255 one by one (or RGBA8, to show that rounding), beside a packed
// depth/stencil buffer of the framework's depth format, so that depth and stencil copy into the
// framework's framebuffer unchanged (a depth/stencil blit needs identical formats). The framework
// reads its own framebuffer (pass snapshots, stencil pictures, shadow masks, the oracle): the
// lesson copies into it.
#pragma once
#include <glm/vec2.hpp>

#include "gl/framebuffer.h"
#include "gl/gl.h"

namespace stencil {

class AccumulationTarget {
 public:
  // size in pixels. Throws UsageError where GL cannot make it (Framebuffer).
  AccumulationTarget(glm::ivec2 size, ColourFormat, DepthFormat);

  bool fits(glm::ivec2 size, ColourFormat, DepthFormat) const;
  void bind() const;  // for drawing and reading, the viewport its whole size
  // Colour (clamped to 0..1 where the destination is RGBA8), depth and stencil into `framebuffer`,
  // which has the same size and depth format; the scissor test applies as to any blit. Leaves this
  // target bound for reading and `framebuffer` for drawing.
  void copyTo(GLuint framebuffer) const;

 private:
  Framebuffer buffer_;
};

}  // namespace stencil
