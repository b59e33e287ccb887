#include "geometry/depth_complexity.h"

#include <algorithm>
#include <stdexcept>

#include "geometry/raycast.h"

namespace stencil {

std::vector<std::uint32_t> depthComplexity(const std::vector<OracleObject>& objects,
                                           const glm::mat4& viewProjection, glm::ivec2 size,
                                           FacesCounted faces) {
  RayScene scene;
  for (const OracleObject& o : objects) {
    if (o.sphere || !o.mesh) throw std::invalid_argument("depthComplexity: every object needs a mesh");
    scene.add(*o.mesh, o.model);
  }
  const glm::dmat4 inverse = glm::inverse(glm::dmat4(viewProjection));
  std::vector<std::uint32_t> counts(static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y), 0);
  for (int py = 0; py < size.y; ++py)
    for (int px = 0; px < size.x; ++px) {
      // From the near plane (t = 0) on; what lies past the far plane is dropped by its clip z.
      const Ray ray = cameraRay(inverse, size, px, py).ray;
      std::uint32_t n = 0;
      for (const RayHit& hit : scene.allHits(ray)) {
        const glm::vec4 clip = viewProjection * glm::vec4(ray.origin + hit.t * ray.direction, 1.0f);
        if (!(clip.w > 0.0f && clip.z <= clip.w)) continue;
        const bool front = glm::dot(hit.normal, ray.direction) < 0.0f;
        if (faces == FacesCounted::All || front == (faces == FacesCounted::Front)) ++n;
      }
      counts[static_cast<std::size_t>(py) * static_cast<std::size_t>(size.x) + static_cast<std::size_t>(px)] =
          n;
    }
  return counts;
}

CountReport compareCounts(const std::vector<std::uint32_t>& expected,
                          const std::vector<std::uint32_t>& actual, glm::ivec2 size) {
  const std::size_t n = static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y);
  if (expected.size() != n || actual.size() != n)
    throw std::invalid_argument("compareCounts: the counts do not match the image size");
  CountReport report;
  report.pixels = n;
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const std::size_t i =
          static_cast<std::size_t>(y) * static_cast<std::size_t>(size.x) + static_cast<std::size_t>(x);
      report.expectedTotal += expected[i];
      report.actualTotal += actual[i];
      if (expected[i] == actual[i]) continue;
      ++report.disagreements;
      bool edge = false;
      for (int dy = -1; dy <= 1 && !edge; ++dy)
        for (int dx = -1; dx <= 1 && !edge; ++dx) {
          const int nx = std::clamp(x + dx, 0, size.x - 1), ny = std::clamp(y + dy, 0, size.y - 1);
          edge = expected[static_cast<std::size_t>(ny) * static_cast<std::size_t>(size.x) +
                          static_cast<std::size_t>(nx)] != expected[i];
        }
      report.onEdges += edge;
    }
  return report;
}

}  // namespace stencil
