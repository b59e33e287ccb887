#include "gl/gpu_mesh.h"

#include <utility>

#include "gl/recorder.h"

namespace stencil {

GpuMesh::GpuMesh(const Mesh& mesh) : indexCount_(static_cast<GLsizei>(mesh.indices.size())) {
  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  glGenBuffers(3, buffers_);
  glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.positions.size() * sizeof(glm::vec3)),
               mesh.positions.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  if (!mesh.normals.empty()) {
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[1]);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.normals.size() * sizeof(glm::vec3)),
                 mesh.normals.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[2]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
}

GpuMesh::~GpuMesh() {
  if (vao_) {
    glDeleteVertexArrays(1, &vao_);
    glDeleteBuffers(3, buffers_);
  }
}

GpuMesh::GpuMesh(GpuMesh&& other) noexcept
    : vao_(std::exchange(other.vao_, 0)), indexCount_(other.indexCount_) {
  std::copy(std::begin(other.buffers_), std::end(other.buffers_), buffers_);
}

GpuMesh& GpuMesh::operator=(GpuMesh&& other) noexcept {
  std::swap(vao_, other.vao_);
  std::swap(buffers_, other.buffers_);
  std::swap(indexCount_, other.indexCount_);
  return *this;
}

void GpuMesh::draw() const {
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
  countDraw(triangles());
}

GpuVertexStream::GpuVertexStream(GLenum mode) : mode_(mode) {
  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  glGenBuffers(1, &buffer_);
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
  glBindVertexArray(0);
}

GpuVertexStream::~GpuVertexStream() {
  glDeleteVertexArrays(1, &vao_);
  glDeleteBuffers(1, &buffer_);
}

void GpuVertexStream::upload(const std::vector<glm::vec4>& vertices) {
  vertexCount_ = static_cast<GLsizei>(vertices.size());
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(glm::vec4)), vertices.data(),
               GL_STREAM_DRAW);  // orphans last frame's contents
}

void GpuVertexStream::draw() const {
  draw(0, vertexCount_);
}

void GpuVertexStream::draw(GLint first, GLsizei count) const {
  glBindVertexArray(vao_);
  glDrawArrays(mode_, first, count);
  countDraw(mode_ == GL_TRIANGLES ? static_cast<std::uint64_t>(count / 3) : 0);
}

WindowRectangle::WindowRectangle() {
  upload({{-1, -1, 0, 1}, {1, -1, 0, 1}, {1, 1, 0, 1}, {-1, -1, 0, 1}, {1, 1, 0, 1}, {-1, 1, 0, 1}});
}

}  // namespace stencil
