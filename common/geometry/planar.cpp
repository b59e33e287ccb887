#include "geometry/planar.h"

#include <glm/geometric.hpp>

namespace stencil {

glm::vec4 planeFrom(glm::vec3 point, glm::vec3 normal) {
  const glm::vec3 n = glm::normalize(normal);
  return {n, -glm::dot(n, point)};
}

float planeDistance(glm::vec4 plane, glm::vec3 point) {
  return glm::dot(glm::vec3(plane), point) + plane.w;
}

glm::mat4 planarShadowMatrix(glm::vec4 plane, glm::vec4 light) {
  const float d = glm::dot(plane, light);
  glm::mat4 m(0.0f);
  for (int col = 0; col < 4; ++col)  // GLM is column-major: m[col][row]
    for (int row = 0; row < 4; ++row) m[col][row] = (row == col ? d : 0.0f) - light[row] * plane[col];
  return m;
}

glm::mat4 reflectionMatrix(glm::vec4 plane) {
  const glm::vec3 n(plane);
  glm::mat4 m(1.0f);
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row) m[col][row] -= 2.0f * n[row] * n[col];
  m[3] = glm::vec4(-2.0f * plane.w * n, 1.0f);
  return m;
}

}  // namespace stencil
