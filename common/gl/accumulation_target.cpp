#include "gl/accumulation_target.h"

namespace stencil {

AccumulationTarget::AccumulationTarget(glm::ivec2 size, ColourFormat colour, DepthFormat depth)
    : buffer_(size.x, size.y, 8, depth, colour) {}

bool AccumulationTarget::fits(glm::ivec2 size, ColourFormat colour, DepthFormat depth) const {
  return size == glm::ivec2(buffer_.width(), buffer_.height()) && colour == buffer_.colourFormat() &&
         depth == buffer_.depthFormat();
}

void AccumulationTarget::bind() const {
  buffer_.bind();
}

void AccumulationTarget::copyTo(GLuint framebuffer) const {
  const int w = buffer_.width(), h = buffer_.height();
  glBindFramebuffer(GL_READ_FRAMEBUFFER, buffer_.id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
  glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
                    GL_NEAREST);
}

}  // namespace stencil
