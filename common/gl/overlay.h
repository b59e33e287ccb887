// A picture made on the CPU (a legend, say) drawn into a frame: uploaded to a texture and blitted,
// so it needs no shader and changes no GL state but the bindings it restores.
#pragma once
#include "gl/gl.h"
#include "gl/image.h"

namespace stencil {

class ImageOverlay {
 public:
  ImageOverlay();
  ~ImageOverlay();
  ImageOverlay(const ImageOverlay&) = delete;
  ImageOverlay& operator=(const ImageOverlay&) = delete;

  // Copies `picture` (RGBA, top row first) into the draw framebuffer bound now, its top left
  // corner `top` pixels below the top of a framebuffer `height` pixels high, at `left` from the
  // left. Colour only; the scissor test applies as to any blit. The draw framebuffer stays bound.
  void draw(const Image& picture, int left, int top, int height);

 private:
  GLuint texture_ = 0, fbo_ = 0;
};

}  // namespace stencil
