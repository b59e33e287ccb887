#include "geometry/projection.h"

namespace stencil {

glm::mat4 reversedDepth(const glm::mat4& projection) {
  glm::mat4 r = projection;
  // glm is column-major: m[column][row]. Row 2 (clip z) becomes (row 3 - row 2) / 2.
  for (int column = 0; column < 4; ++column)
    r[column][2] = 0.5f * (projection[column][3] - projection[column][2]);
  return r;
}

}  // namespace stencil
