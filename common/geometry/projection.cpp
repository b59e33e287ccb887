#include "geometry/projection.h"

namespace stencil {

glm::mat4 reversedDepth(const glm::mat4& projection) {
  glm::mat4 r = projection;
  // glm is column-major: m[column][row]. Row 2 (clip z) becomes (row 3 - row 2) / 2.
  for (int column = 0; column < 4; ++column)
    r[column][2] = 0.5f * (projection[column][3] - projection[column][2]);
  return r;
}

glm::vec3 drawingOrigin(const glm::vec3& eye) { return glm::round(eye / 1024.0f) * 1024.0f; }

glm::mat4 viewProjectionFrom(const glm::mat4& viewProjection, const glm::vec3& origin) {
  glm::dmat4 translate(1.0);
  translate[3] = glm::dvec4(glm::dvec3(origin), 1.0);
  return glm::mat4(glm::dmat4(viewProjection) * translate);
}

}  // namespace stencil
