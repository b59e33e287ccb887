// One shadow caster on the GPU for McGuire et al.'s volumes (geometry/fast_shadows.h): its
// doubled vertex array (static), an index buffer rewritten per light (sides, dark cap, light cap
// and silhouette lines one after the other, as volumeOf lists them), and the few split
// dark-cap triangles as vertices. Attribute 0 is a vec4, for shaders/common/extrude.vert.
#pragma once
#include <cstdint>
#include <glm/vec4.hpp>
#include <vector>

#include "geometry/mesh.h"
#include "gl/gl.h"

namespace stencil {

class DoubledCaster {
 public:
  explicit DoubledCaster(const Mesh& welded);
  ~DoubledCaster();
  DoubledCaster(const DoubledCaster&) = delete;
  DoubledCaster& operator=(const DoubledCaster&) = delete;

  void upload(const std::vector<std::uint32_t>& indices, const std::vector<glm::vec4>& split);
  // Indices [first, first + count) of the uploaded list, as triangles (or lines).
  void draw(std::size_t first, std::size_t count, GLenum mode = GL_TRIANGLES) const;
  // The split dark-cap triangles.
  void drawSplit() const;

 private:
  GLuint vao_[2] = {0, 0}, buffers_[3] = {0, 0, 0};
  GLsizei splitVertices_ = 0;
};

}  // namespace stencil
