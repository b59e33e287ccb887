// The off-screen framebuffer every lesson renders into: RGBA8 colour plus a packed
// depth24/stencil8 attachment. Its stencil bits are verified, never assumed from a
// pixel format, so every backend gives the same stencil buffer.
#pragma once
#include "gl/gl.h"
#include "gl/image.h"

namespace stencil {

// Reads the colour of any framebuffer (0: the window's), RGBA, top row first, opaque.
Image readColourPixels(GLuint framebuffer, int width, int height);

class Framebuffer {
 public:
  // stencilBits is 8 for lessons; 0 builds one without stencil (to test the check).
  Framebuffer(int width, int height, int stencilBits = 8);
  ~Framebuffer();
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  void bind() const;  // binds for drawing and sets the viewport to the whole buffer
  int width() const { return width_; }
  int height() const { return height_; }
  GLuint id() const { return fbo_; }
  int stencilBits() const { return stencilBits_; }  // as queried from GL

  Image readColour() const;   // RGBA, top row first, alpha 255
  Image readStencil() const;  // one byte per pixel, top row first

 private:
  int width_, height_;
  int stencilBits_ = 0;
  GLuint fbo_ = 0, colour_ = 0, depthStencil_ = 0;
};

}  // namespace stencil
