#include "geometry/mirror.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <stdexcept>

#include "geometry/planar.h"

namespace stencil {
namespace {

glm::vec4 normalisedPlane(glm::vec4 p) {
  return p / glm::length(glm::vec3(p));
}

}  // namespace

bool facesEye(glm::vec4 mirrorPlane, glm::vec3 eye) {
  return planeDistance(mirrorPlane, eye) > 0.0f;
}

Frustum throughMirror(const Frustum& parent, glm::vec3 eye, const std::vector<glm::vec3>& polygon,
                      glm::vec4 mirrorPlane) {
  if (polygon.size() < 3) throw std::invalid_argument("throughMirror: a mirror needs at least 3 corners");
  if (!facesEye(mirrorPlane, eye)) throw std::invalid_argument("throughMirror: the eye is behind the mirror");
  const glm::mat4 reflect = reflectionMatrix(mirrorPlane);
  const glm::vec3 virtualEye = glm::vec3(reflect * glm::vec4(eye, 1.0f));
  glm::vec3 centre(0.0f);
  for (const glm::vec3& c : polygon) centre += c;
  centre /= static_cast<float>(polygon.size());

  Frustum f;
  f.planes.push_back(mirrorPlane);  // only what stands on the reflective side is reflected
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::vec3 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    const glm::vec3 n = glm::cross(a - virtualEye, b - virtualEye);
    if (glm::length(n) == 0.0f) continue;  // an edge in line with the eye bounds nothing
    glm::vec4 side = normalisedPlane({n, -glm::dot(n, virtualEye)});
    if (planeDistance(side, centre) < 0.0f) side = -side;  // the polygon's inside is inside
    f.planes.push_back(side);
  }
  for (const glm::vec4& p : parent.planes) f.planes.push_back(transformPlane(p, reflect));
  return f;
}

std::uint64_t worstCaseRenderings(int mirrors, int depth) {
  if (mirrors < 1 || depth < 0) throw std::invalid_argument("worstCaseRenderings: n >= 1 and r >= 0");
  std::uint64_t total = 1, perMirror = 1;  // (n-1)^(i-1) at bounce i
  for (int i = 1; i <= depth; ++i) {
    total += static_cast<std::uint64_t>(mirrors) * perMirror;
    perMirror *= static_cast<std::uint64_t>(mirrors - 1);
  }
  return total;
}

glm::mat4 withFarPlane(const glm::mat4& projection, float farPlane) {
  // glm::perspective: m[2][2] = -(f + n) / (f - n), m[3][2] = -2 f n / (f - n).
  const float nearPlane = projection[3][2] / (projection[2][2] - 1.0f);
  glm::mat4 p = projection;
  p[2][2] = -(farPlane + nearPlane) / (farPlane - nearPlane);
  p[3][2] = -2.0f * farPlane * nearPlane / (farPlane - nearPlane);
  return p;
}

}  // namespace stencil
