#include "gl/framebuffer.h"

#include <algorithm>
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
