#pragma once

// Bounding volumes, e.g. to place a light outside a scene or to fit a shadow
// volume's extrusion distance. Points are expected to be finite.
//
// Depends on: GLM (C++17).

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <vector>

namespace stencil {

struct Aabb {
  // Starts inverted (min > max) so the first extend() sets both corners.
  glm::vec3 min{std::numeric_limits<float>::infinity()};
  glm::vec3 max{-std::numeric_limits<float>::infinity()};

  bool empty() const;        // true until something was added
  glm::vec3 centre() const;  // (0,0,0) when empty
  glm::vec3 extent() const;  // full size, max - min; (0,0,0) when empty
  void extend(glm::vec3 point);
};

Aabb boundsOf(const std::vector<glm::vec3>& points);

// Box around the 8 transformed corners (affine matrix). Exact for the box
// itself, so usually looser than re-bounding the transformed points.
// An empty box stays empty.
Aabb transformedBounds(const Aabb& box, const glm::mat4& matrix);

struct BoundingSphere {
  glm::vec3 centre{0.0f};
  float radius = 0.0f;
};

// Contains every point: the smaller of Ritter's sphere and the sphere around
// the AABB centre, each with its radius set to the farthest point actually
// measured, then nudged up a few ulps so a caller's own float distance check
// cannot exclude a point by rounding. Not the minimal sphere, but never larger
// than half the AABB diagonal. Throws std::invalid_argument for no points.
BoundingSphere boundingSphereOf(const std::vector<glm::vec3>& points);

}  // namespace stencil
