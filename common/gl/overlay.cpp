#include "gl/overlay.h"

#include <stdexcept>

namespace stencil {

ImageOverlay::ImageOverlay() {
  glGenTextures(1, &texture_);
  glGenFramebuffers(1, &fbo_);
}

ImageOverlay::~ImageOverlay() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteTextures(1, &texture_);
}

void ImageOverlay::draw(const Image& picture, int left, int top, int height) {
  if (picture.channels != 4) throw std::invalid_argument("ImageOverlay::draw: the picture must be RGBA");
  GLint target = 0, read = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, picture.width, picture.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               picture.pixels.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glBindTexture(GL_TEXTURE_2D, 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
  // The texture's first row is the picture's top: the blit turns it upside down onto GL's rows.
  const int y1 = height - top, y0 = y1 - picture.height;
  glBlitFramebuffer(0, 0, picture.width, picture.height, left, y1, left + picture.width, y0,
                    GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read));
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(target));
}

}  // namespace stencil
