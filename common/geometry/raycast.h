#pragma once

// Exact CPU ray casting against triangle meshes, with no OpenGL: an oracle that
// answers "what does this pixel see?" and "is this point in shadow?"
// independently of the stencil passes it is used to check.
//
// Depends on: GLM, mesh (C++17).

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <optional>
#include <vector>

#include "geometry/mesh.h"

namespace stencil {

// A ray p(t) = origin + t * direction; direction need not be unit length.
struct Ray {
  glm::vec3 origin;
  glm::vec3 direction;
};

// Möller–Trumbore, two-sided. The t of the hit if it is in (tMin, tMax), else nullopt.
// Degenerate triangles and rays parallel to the triangle never hit. Edges and corners
// count as inside, so a ray through an edge shared by two triangles hits both, and a
// closed mesh has no cracks.
std::optional<float> intersectTriangle(const Ray& ray, const glm::vec3& a, const glm::vec3& b,
                                       const glm::vec3& c, float tMin = 0.0f, float tMax = INFINITY);

// The true sphere, for oracles that judge a tessellated one: the nearest t in (tMin, tMax)
// where the ray meets the sphere's surface (from outside or inside), else nullopt. Solved in
// double precision; a ray that only grazes it (a double root) counts as a hit.
std::optional<float> intersectSphere(const Ray& ray, const glm::vec3& centre, float radius, float tMin = 0.0f,
                                     float tMax = INFINITY);

struct RayHit {
  float t;
  int object;    // as returned by RayScene::add
  int triangle;  // index of the triangle in that object's mesh (indices / 3)
  // Unit geometric normal of the hit triangle in world space, as wound (counter-clockwise
  // front): (b - a) x (c - a), whichever side the ray came from.
  glm::vec3 normal;
};

// Triangles of several meshes placed in world space, for exact ray queries (no GL).
// Each object gets a bounding-volume hierarchy (axis-aligned boxes, split at the median of
// the longest axis, a few triangles per leaf) so a 320x240 image of camera rays plus one
// shadow ray per pixel against a few thousand triangles takes well under a second.
//
// A shadow ray that starts on a surface hits that surface again at t ~ 0: pass a small
// tMin (or start off the surface) so a lit point does not shadow itself.
class RayScene {
 public:
  // Transforms positions once, as transformed() in mesh.h does: a mirroring model matrix
  // keeps the triangles outward-facing. Returns the object id (0, 1, ...). Throws
  // std::invalid_argument for a broken mesh (validateMesh), a non-finite vertex, or a
  // model matrix that is projective or singular; the scene is unchanged then.
  int add(const Mesh& mesh, const glm::mat4& model);

  // The nearest hit with t in (tMin, tMax) over all objects.
  std::optional<RayHit> firstHit(const Ray& ray, float tMin = 0.0f, float tMax = INFINITY) const;

  // Any hit with t in (tMin, tMax) among the objects for which casts(object) is true (all
  // when empty); stops at the first.
  bool occluded(const Ray& ray, float tMin, float tMax, const std::function<bool(int)>& casts = {}) const;

  // Every hit with t in (tMin, tMax), over all objects, in no particular order: what a ray
  // crosses on its way (depth complexity, geometry/depth_complexity.h). A ray through an edge
  // shared by two triangles hits both, as firstHit's edges do.
  std::vector<RayHit> allHits(const Ray& ray, float tMin = 0.0f, float tMax = INFINITY) const;

  std::size_t objectCount() const;

 private:
  struct Node {
    glm::vec3 min, max;
    // A leaf (count > 0) holds the triangle slots [first, first + count). An inner node
    // (count == 0) has its left child right after it and its right child at `first`.
    std::uint32_t first = 0;
    std::uint32_t count = 0;
  };
  struct Object {
    std::vector<Node> nodes;             // nodes[0] is the root; empty for a mesh without triangles
    std::vector<glm::vec3> corners;      // 3 world-space corners per slot, in leaf order
    std::vector<std::int32_t> triangle;  // the mesh triangle in each slot
  };
  std::vector<Object> objects_;
};

// The camera's ray through the centre of pixel (x, yTop) of a size.x by size.y picture (yTop counts
// rows from the top): the centre unprojected at the near and far planes through
// inverseViewProjection (GL clip conventions, in double, then rounded to float), t in
// [0, tMax = 1] spanning the view frustum. With the far plane at infinity the far point is a
// direction (w = 0): the ray then goes through the centre unprojected half way in depth instead,
// and on without end (tMax infinite). The oracle's, the CSG ray cast's and the depth-complexity
// count's pixel rays.
struct CameraRay {
  Ray ray;
  float tMax;
};
CameraRay cameraRay(const glm::dmat4& inverseViewProjection, glm::ivec2 size, int x, int yTop);

// The ray from a point towards a homogeneous light (w = 1: a point light, w = 0: a direction
// towards the light) and the t range that reaches it: (0, 1] for a point light, (0, inf) for a direction.
// Any other w != 0 is the point light at xyz / w; a point at the light itself gets a zero
// direction, which nothing occludes. Throws std::invalid_argument for a non-finite light or
// a directional light of zero length.
struct LightRay {
  Ray ray;
  float tMax;
};
LightRay rayTowardsLight(const glm::vec3& point, const glm::vec4& light);

}  // namespace stencil
