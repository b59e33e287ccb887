#include "gl/doubled_caster.h"

#include "geometry/fast_shadows.h"
#include "gl/recorder.h"

namespace stencil {

DoubledCaster::DoubledCaster(const Mesh& welded) {
  const std::vector<glm::vec4> vertices = doubledVertexArray(welded);
  glGenVertexArrays(2, vao_);
  glGenBuffers(3, buffers_);
  glBindVertexArray(vao_[0]);
  glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(glm::vec4)), vertices.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[1]);
  glBindVertexArray(vao_[1]);
  glBindBuffer(GL_ARRAY_BUFFER, buffers_[2]);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
  glBindVertexArray(0);
}

DoubledCaster::~DoubledCaster() {
  glDeleteVertexArrays(2, vao_);
  glDeleteBuffers(3, buffers_);
}

void DoubledCaster::upload(const std::vector<std::uint32_t>& indices, const std::vector<glm::vec4>& split) {
  glBindVertexArray(vao_[0]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)),
               indices.data(), GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, buffers_[2]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(split.size() * sizeof(glm::vec4)), split.data(),
               GL_STREAM_DRAW);
  splitVertices_ = static_cast<GLsizei>(split.size());
  glBindVertexArray(0);
}

void DoubledCaster::draw(std::size_t first, std::size_t count, GLenum mode) const {
  if (count == 0) return;
  glBindVertexArray(vao_[0]);
  glDrawElements(mode, static_cast<GLsizei>(count), GL_UNSIGNED_INT,
                 reinterpret_cast<const void*>(first * sizeof(std::uint32_t)));
  countDraw(mode == GL_TRIANGLES ? count / 3 : 0);
}

void DoubledCaster::drawSplit() const {
  if (splitVertices_ == 0) return;
  glBindVertexArray(vao_[1]);
  glDrawArrays(GL_TRIANGLES, 0, splitVertices_);
  countDraw(static_cast<std::uint64_t>(splitVertices_ / 3));
}

}  // namespace stencil
