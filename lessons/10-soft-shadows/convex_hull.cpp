// The convex hull each penumbra wedge is drawn as (main.cpp's penumbraWedges): the edge's two
// endpoints and their eight extrusions, every face found by brute force over triples.
// (geometry/soft_shadow.h's convexHull is the planar one.)
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "soft_shadows.h"

namespace stencil::soft_shadows {

// The convex hull of a few points (a dozen: every plane through three of them with all the others
// on one side holds a face), as triangles counter-clockwise seen from outside, w = 1. Points
// within 1e-6 of the hull's size from a face's plane belong to that face. Empty when the points
// span no volume.
std::vector<glm::vec4> convexHullTriangles(const std::vector<glm::dvec3>& p) {
  std::vector<glm::vec4> triangles;
  double size = 0.0;
  for (const glm::dvec3& q : p) size = std::max(size, glm::length(q - p[0]));
  const double eps = 1e-6 * size;
  std::vector<std::vector<std::size_t>> faces;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      for (std::size_t k = j + 1; k < p.size(); ++k) {
        glm::dvec3 normal = glm::cross(p[j] - p[i], p[k] - p[i]);
        const double length = glm::length(normal);
        if (length <= 1e-12 * size * size) continue;
        normal /= length;
        bool below = true, above = true;
        std::vector<std::size_t> on;
        for (std::size_t m = 0; m < p.size(); ++m) {
          const double d = glm::dot(normal, p[m] - p[i]);
          if (d > eps) below = false;
          if (d < -eps) above = false;
          if (std::abs(d) <= eps) on.push_back(m);
        }
        if (below == above) continue;  // points on both sides, or all on the plane
        if (!below) normal = -normal;  // outward: the others lie behind the face
        if (std::find(faces.begin(), faces.end(), on) != faces.end()) continue;
        faces.push_back(on);
        // The face's points in order: a 2D hull (monotone chain) in the plane's (u, v), u x v the
        // outward normal, so counter-clockwise there is counter-clockwise from outside.
        const glm::dvec3 u = glm::normalize(p[on[1]] - p[on[0]]), v = glm::cross(normal, u);
        std::vector<std::pair<glm::dvec2, std::size_t>> flat;
        for (std::size_t m : on) flat.push_back({{glm::dot(p[m], u), glm::dot(p[m], v)}, m});
        std::sort(flat.begin(), flat.end(), [](const auto& a, const auto& b) {
          return a.first.x < b.first.x || (a.first.x == b.first.x && a.first.y < b.first.y);
        });
        auto turn = [](glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) {
          return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
        };
        std::vector<std::size_t> ring;  // positions in flat
        for (int pass = 0; pass < 2; ++pass) {
          const std::size_t start = ring.size();
          for (std::size_t t = 0; t < flat.size(); ++t) {
            const std::size_t at = pass == 0 ? t : flat.size() - 1 - t;
            while (ring.size() >= start + 2 && turn(flat[ring[ring.size() - 2]].first,
                                                    flat[ring.back()].first, flat[at].first) <= eps * size)
              ring.pop_back();
            ring.push_back(at);
          }
          ring.pop_back();  // the chain's last point starts the other chain
        }
        for (std::size_t t = 1; t + 1 < ring.size(); ++t)
          for (std::size_t corner : {ring[0], ring[t], ring[t + 1]})
            triangles.push_back(glm::vec4(glm::vec3(p[flat[corner].second]), 1.0f));
      }
  return triangles;
}

}  // namespace stencil::soft_shadows
