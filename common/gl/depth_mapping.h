// The depth mapping a frame draws with (Frame::reversedDepth; lesson 15 teaches it). Reversed:
// window depth is clip z / w, 1 at the near plane and n/d at distance d, which a float depth
// buffer holds to about 2^-24 of d at every distance; nearer is then greater, and every depth
// comparison flips. Else GL's default mapping, 0 near and 1 far. The lesson makes the GL calls
// itself, before it clears or draws anything:
//   if (f.reversedDepth) glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // no 0.5 + 0.5 z/w
//   glClearDepth(mapping.farthest);
#pragma once
#include <glm/glm.hpp>

#include "geometry/projection.h"
#include "gl/gl.h"
#include "gl/lesson.h"

namespace stencil {

struct DepthMapping {
  GLenum less = GL_LESS, lequal = GL_LEQUAL;  // GL_GREATER and GL_GEQUAL reversed
  double farthest = 1.0;                      // the clear depth, the depth of infinity: 0 reversed
  glm::mat4 projection{1.0f};                 // Frame::projection, or its reversedDepth (near 1, infinity 0)
};

inline DepthMapping depthMappingOf(const Frame& f) {
  if (!f.reversedDepth) return {GL_LESS, GL_LEQUAL, 1.0, f.projection};
  return {GL_GREATER, GL_GEQUAL, 0.0, reversedDepth(f.projection)};
}

}  // namespace stencil
