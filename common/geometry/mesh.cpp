#include "geometry/mesh.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vec4.hpp>
#include <stdexcept>
#include <string>
#include <utility>

namespace stencil {

namespace {

bool isFinite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

std::size_t Mesh::triangleCount() const {
  return indices.size() / 3;
}

void validateMesh(const Mesh& mesh) {
  if (mesh.indices.size() % 3 != 0) {
    throw std::invalid_argument("mesh: index count " + std::to_string(mesh.indices.size()) +
                                " is not a multiple of 3");
  }
  if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size()) {
    throw std::invalid_argument("mesh: " + std::to_string(mesh.normals.size()) + " normals for " +
                                std::to_string(mesh.positions.size()) + " positions");
  }
  const std::size_t vertexCount = mesh.positions.size();
  for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
    if (mesh.indices[i] >= vertexCount) {
      throw std::invalid_argument("mesh: index " + std::to_string(mesh.indices[i]) + " at position " +
                                  std::to_string(i) + " is out of range (" + std::to_string(vertexCount) +
                                  " vertices)");
    }
  }
}

std::optional<std::size_t> firstNonFiniteVertex(const Mesh& mesh) {
  const bool hasNormals = !mesh.normals.empty();
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    if (!isFinite(mesh.positions[i])) {
      return i;
    }
    if (hasNormals && i < mesh.normals.size() && !isFinite(mesh.normals[i])) {
      return i;
    }
  }
  return std::nullopt;
}

bool allFinite(const Mesh& mesh) {
  return !firstNonFiniteVertex(mesh).has_value();
}

Mesh transformed(const Mesh& mesh, const glm::mat4& matrix) {
  validateMesh(mesh);
  // glm is column-major: matrix[c][3] is the bottom row.
  if (matrix[0][3] != 0.0f || matrix[1][3] != 0.0f || matrix[2][3] != 0.0f || matrix[3][3] != 1.0f) {
    throw std::invalid_argument("transformed: matrix is not affine (bottom row must be 0,0,0,1)");
  }
  const glm::mat3 linear(matrix);
  const float det = glm::determinant(linear);
  if (!std::isfinite(det) || det == 0.0f) {
    throw std::invalid_argument("transformed: matrix is singular, normals would be undefined");
  }
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(linear));

  Mesh out;
  out.positions.reserve(mesh.positions.size());
  for (const glm::vec3& p : mesh.positions) {
    out.positions.emplace_back(matrix * glm::vec4(p, 1.0f));
  }
  out.normals.reserve(mesh.normals.size());
  for (const glm::vec3& n : mesh.normals) {
    const glm::vec3 t = normalMatrix * n;
    const float len = glm::length(t);
    // A zero input normal has no direction to preserve; keep it zero rather than NaN.
    out.normals.push_back(len > 0.0f ? t / len : t);
  }
  out.indices = mesh.indices;
  if (det < 0.0f) {
    for (std::size_t t = 0; t + 2 < out.indices.size(); t += 3) {
      std::swap(out.indices[t + 1], out.indices[t + 2]);
    }
  }
  return out;
}

double signedVolume(const Mesh& mesh) {
  validateMesh(mesh);
  // Double accumulation: big meshes sum many small terms of both signs.
  double sixTimesVolume = 0.0;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const glm::dvec3 a(mesh.positions[mesh.indices[t]]);
    const glm::dvec3 b(mesh.positions[mesh.indices[t + 1]]);
    const glm::dvec3 c(mesh.positions[mesh.indices[t + 2]]);
    sixTimesVolume += glm::dot(a, glm::cross(b, c));
  }
  return sixTimesVolume / 6.0;
}

}  // namespace stencil
