#include "geometry/bounds.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <stdexcept>

namespace stencil {

bool Aabb::empty() const {
  return min.x > max.x || min.y > max.y || min.z > max.z;
}

glm::vec3 Aabb::centre() const {
  return empty() ? glm::vec3(0.0f) : (min + max) * 0.5f;
}

glm::vec3 Aabb::extent() const {
  return empty() ? glm::vec3(0.0f) : max - min;
}

void Aabb::extend(glm::vec3 point) {
  min = glm::min(min, point);
  max = glm::max(max, point);
}

Aabb boundsOf(const std::vector<glm::vec3>& points) {
  Aabb box;
  for (const glm::vec3& p : points) {
    box.extend(p);
  }
  return box;
}

Aabb transformedBounds(const Aabb& box, const glm::mat4& matrix) {
  Aabb out;
  if (box.empty()) {
    return out;
  }
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                      (corner & 4) ? box.max.z : box.min.z);
    out.extend(glm::vec3(matrix * glm::vec4(p, 1.0f)));
  }
  return out;
}

namespace {

std::size_t farthestFrom(const std::vector<glm::vec3>& points, glm::vec3 from) {
  std::size_t best = 0;
  float bestDistanceSquared = -1.0f;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const glm::vec3 d = points[i] - from;
    const float distanceSquared = glm::dot(d, d);
    if (distanceSquared > bestDistanceSquared) {
      bestDistanceSquared = distanceSquared;
      best = i;
    }
  }
  return best;
}

// Radius that really contains every point around `centre`, measured in double.
float enclosingRadius(const std::vector<glm::vec3>& points, glm::vec3 centre) {
  double farthest = 0.0;
  for (const glm::vec3& p : points) {
    farthest = std::max(farthest, glm::length(glm::dvec3(p) - glm::dvec3(centre)));
  }
  const auto radius = static_cast<float>(farthest);
  // The float cast can round down, and callers compare float distances.
  return radius * (1.0f + 4.0f * std::numeric_limits<float>::epsilon()) +
         std::numeric_limits<float>::denorm_min();
}

glm::vec3 ritterCentre(const std::vector<glm::vec3>& points) {
  // Two passes for a good initial diameter, then grow just enough to take in
  // each outside point.
  const glm::vec3 a = points[farthestFrom(points, points[0])];
  const glm::vec3 b = points[farthestFrom(points, a)];
  glm::dvec3 centre = (glm::dvec3(a) + glm::dvec3(b)) * 0.5;
  double radius = glm::length(glm::dvec3(b) - glm::dvec3(a)) * 0.5;
  for (const glm::vec3& p : points) {
    const double distance = glm::length(glm::dvec3(p) - centre);
    if (distance > radius) {
      const double grown = (radius + distance) * 0.5;
      centre += (glm::dvec3(p) - centre) * ((grown - radius) / distance);
      radius = grown;
    }
  }
  return glm::vec3(centre);
}

}  // namespace

BoundingSphere boundingSphereOf(const std::vector<glm::vec3>& points) {
  if (points.empty()) {
    throw std::invalid_argument("boundingSphereOf: no points");
  }
  const glm::vec3 boxCentre = boundsOf(points).centre();
  const BoundingSphere aroundBox{boxCentre, enclosingRadius(points, boxCentre)};
  const glm::vec3 ritter = ritterCentre(points);
  const BoundingSphere aroundRitter{ritter, enclosingRadius(points, ritter)};
  return aroundRitter.radius < aroundBox.radius ? aroundRitter : aroundBox;
}

}  // namespace stencil
