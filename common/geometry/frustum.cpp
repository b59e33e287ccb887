#include "geometry/frustum.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace stencil {
namespace {

Plane normalisedPlane(Plane p) {
  return p / glm::length(glm::vec3(p));
}

float side(const Plane& p, const glm::vec3& point) {
  return glm::dot(glm::vec3(p), point) + p.w;
}

}  // namespace

Frustum viewFrustum(const glm::mat4& m, bool withFar) {
  // GLM is column-major: row i of the matrix is (m[0][i], m[1][i], m[2][i], m[3][i]).
  const auto row = [&](int i) { return glm::vec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
  const glm::vec4 w = row(3);
  Frustum f{{w + row(0), w - row(0), w + row(1), w - row(1), w + row(2)}};
  if (withFar) f.planes.push_back(w - row(2));
  for (Plane& p : f.planes) p = normalisedPlane(p);
  return f;
}

Plane transformPlane(Plane plane, const glm::mat4& matrix) {
  // Points map x -> M x, so planes map as row vectors p -> p M^-1.
  return normalisedPlane(glm::transpose(glm::inverse(matrix)) * plane);
}

bool outside(const Frustum& f, const BoundingSphere& s) {
  for (const Plane& p : f.planes) {
    const float length = glm::length(glm::vec3(p));
    if (length == 0.0f) continue;
    if (side(p, s.centre) / length < -s.radius) return true;
  }
  return false;
}

bool outside(const Frustum& f, const std::vector<glm::vec3>& points) {
  for (const Plane& p : f.planes) {
    bool allBehind = true;
    for (const glm::vec3& x : points) allBehind = allBehind && side(p, x) < 0.0f;
    if (allBehind) return true;
  }
  return false;
}

}  // namespace stencil
