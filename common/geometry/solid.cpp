#include "geometry/solid.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace stencil {

int windingNumber(const Mesh& mesh, const glm::dvec3& point) {
  double total = 0.0;
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    // Van Oosterom and Strackee: the solid angle of triangle abc seen from the origin.
    const glm::dvec3 a = glm::dvec3(mesh.positions[mesh.indices[i]]) - point;
    const glm::dvec3 b = glm::dvec3(mesh.positions[mesh.indices[i + 1]]) - point;
    const glm::dvec3 c = glm::dvec3(mesh.positions[mesh.indices[i + 2]]) - point;
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    const double numerator = glm::dot(a, glm::cross(b, c));
    const double denominator = la * lb * lc + glm::dot(a, b) * lc + glm::dot(b, c) * la + glm::dot(c, a) * lb;
    total += 2.0 * std::atan2(numerator, denominator);
  }
  return static_cast<int>(std::lround(total / (4.0 * M_PI)));
}

SolidSide solidSide(const Mesh& mesh, bool facesIn, const glm::vec3& eye) {
  return {facesIn, windingNumber(mesh, glm::dvec3(eye)) != 0};
}

bool lightBuried(const Mesh& mesh, const SolidSide& side, const glm::vec4& light) {
  if (light.w == 0.0f) return side.room;
  const bool enclosed = windingNumber(mesh, glm::dvec3(glm::vec3(light) / light.w)) != 0;
  return side.room ? !enclosed : enclosed;
}

}  // namespace stencil
