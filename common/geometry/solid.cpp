#include "geometry/solid.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace stencil {

namespace {

// The solid angles the triangles subtend from the point, summed, over 4 pi.
double windingOf(const Mesh& mesh, const glm::dvec3& point) {
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
  return total / (4.0 * M_PI);
}

}  // namespace

int windingNumber(const Mesh& mesh, const glm::dvec3& point) {
  return static_cast<int>(std::lround(windingOf(mesh, point)));
}

namespace {

// The distance from p to triangle abc (Ericson, "Real-Time Collision Detection", 5.1.5: the
// closest point by the region of the triangle's plane p projects into).
double distanceToTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                          const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return glm::length(ap);
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return glm::length(bp);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return glm::length(p - (a + ab * (d1 / (d1 - d3))));
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return glm::length(cp);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return glm::length(p - (a + ac * (d2 / (d2 - d6))));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return glm::length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
  const double denominator = va + vb + vc;
  if (denominator == 0.0) return glm::length(ap);  // a degenerate triangle: its first corner
  return glm::length(p - (a + ab * (vb / denominator) + ac * (vc / denominator)));
}

}  // namespace

bool onSurface(const Mesh& mesh, const glm::dvec3& point) {
  double size = 0.0;
  for (const glm::vec3& v : mesh.positions) size = std::max(size, double(glm::length(glm::dvec3(v) - point)));
  const double tolerance = 1e-6 * std::max(1.0, size + glm::length(point));
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
    if (distanceToTriangle(point, glm::dvec3(mesh.positions[mesh.indices[i]]),
                           glm::dvec3(mesh.positions[mesh.indices[i + 1]]),
                           glm::dvec3(mesh.positions[mesh.indices[i + 2]])) <= tolerance)
      return true;
  return false;
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
