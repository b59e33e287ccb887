// Geometry uploaded to GL. GpuMesh: a Mesh, positions at attribute 0, normals at attribute 1.
// GpuTriangles: homogeneous triangles rebuilt on the CPU as the scene moves (shadow volumes),
// vec4 positions at attribute 0, for shaders/common/volume.vert. GpuLines: the same for line
// segments, two vertices each (silhouette edges shown in the window).
#pragma once
#include <cstdint>
#include <glm/vec4.hpp>
#include <vector>

#include "geometry/mesh.h"
#include "gl/gl.h"

namespace stencil {

class GpuMesh {
 public:
  explicit GpuMesh(const Mesh&);
  ~GpuMesh();
  GpuMesh(GpuMesh&&) noexcept;
  GpuMesh& operator=(GpuMesh&&) noexcept;
  GpuMesh(const GpuMesh&) = delete;
  GpuMesh& operator=(const GpuMesh&) = delete;

  // One indexed draw call, counted by the pass recorder for --stats.
  void draw() const;
  std::uint64_t triangles() const { return indexCount_ / 3; }

 private:
  GLuint vao_ = 0, buffers_[3] = {0, 0, 0};
  GLsizei indexCount_ = 0;
};

// Homogeneous vertices (vec4: w = 0 for points at infinity) replaced each frame and drawn as one
// primitive type: shadow volumes built on the CPU, silhouettes as lines.
class GpuVertexStream {
 public:
  explicit GpuVertexStream(GLenum mode);
  ~GpuVertexStream();
  GpuVertexStream(const GpuVertexStream&) = delete;
  GpuVertexStream& operator=(const GpuVertexStream&) = delete;

  // Replaces the contents.
  void upload(const std::vector<glm::vec4>& vertices);
  // One draw call, counted by the pass recorder for --stats.
  void draw() const;
  // One draw call of `count` vertices from `first` (a piece of what was uploaded).
  void draw(GLint first, GLsizei count) const;
  std::uint64_t triangles() const {
    return mode_ == GL_TRIANGLES ? static_cast<std::uint64_t>(vertexCount_ / 3) : 0;
  }

 private:
  GLenum mode_;
  GLuint vao_ = 0, buffer_ = 0;
  GLsizei vertexCount_ = 0;
};

// Three vertices per triangle.
struct GpuTriangles : GpuVertexStream {
  GpuTriangles() : GpuVertexStream(GL_TRIANGLES) {}
};

// The whole window as two triangles in clip space (z = 0, w = 1), for a pass that touches every
// pixel the scissor lets through: drawn with an identity transform.
struct WindowRectangle : GpuTriangles {
  WindowRectangle();
};

// Two vertices per segment.
struct GpuLines : GpuVertexStream {
  GpuLines() : GpuVertexStream(GL_LINES) {}
};

}  // namespace stencil
