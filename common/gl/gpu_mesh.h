// A Mesh uploaded to GL: positions at attribute 0, normals at attribute 1.
#pragma once
#include <cstdint>

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

}  // namespace stencil
