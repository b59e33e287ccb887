#include "geometry/raycast.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace stencil {

namespace {

// Below this |sin| of the angle between the edges, or between the ray and the plane, a
// triangle counts as degenerate or the ray as parallel. A few float roundings in the
// determinant come to ~3e-7, so a truly collinear triangle is caught with margin.
constexpr double kParallelSine = 1e-6;

constexpr std::uint32_t kLeafSize = 4;

// Watertight: Woop, Benthin & Wald, "Watertight Ray/Triangle Intersection" (JCGT 2013). The
// corners are moved to the ray's origin and sheared so that the ray runs down the z axis; the
// edge functions U, V, W are then 2D cross products of corners, and an edge shared by two
// triangles (the same two corner positions) gives the same value in both, negated, bit for bit:
// no ray passes between two triangles. A ray through a shared edge or corner (an edge function
// exactly 0, in double as well) is given to exactly one of the triangles that meet there, by a
// rule on the edge's direction (as a rasterizer's top-left rule gives a pixel centre on a shared
// edge to one triangle), reversed for a triangle seen from behind, so that a ray grazing a
// silhouette edge crosses both of its faces or neither: a closed surface is crossed as often in
// as out. The comparisons are written so that a NaN anywhere reads as a miss.
struct Sheared {
  double x, y;
};

// Whether a ray exactly on the edge from p to q (sheared corners) goes to a triangle seen from the
// front that runs along the edge in this direction; its neighbour runs along it the other way.
inline bool ownsEdge(const Sheared& p, const Sheared& q) {
  const double dx = q.x - p.x, dy = q.y - p.y;
  return dy > 0.0 || (dy == 0.0 && dx < 0.0);
}

inline bool hitTriangle(const glm::vec3& origin, const glm::vec3& direction, const glm::vec3& a,
                        const glm::vec3& b, const glm::vec3& c, float tMin, float tMax, float& tOut) {
  // The ray's largest axis becomes z, x and y follow it. The line is sheared as if the ray pointed
  // up z (`along`: its direction or the opposite): which triangles a line meets, at an edge too,
  // does not depend on which way the ray runs along it; t follows the ray's own direction.
  const glm::vec3 magnitude = glm::abs(direction);
  const int kz = magnitude.x > magnitude.y ? (magnitude.x > magnitude.z ? 0 : 2) : (magnitude.y > magnitude.z ? 1 : 2);
  const int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  if (!(direction[kz] != 0.0f)) return false;
  const float way = direction[kz] < 0.0f ? -1.0f : 1.0f;
  const glm::vec3 along = way * direction;
  const float sx = along[kx] / along[kz], sy = along[ky] / along[kz], sz = 1.0f / along[kz];
  const glm::vec3 pa = a - origin, pb = b - origin, pc = c - origin;
  const float ax = pa[kx] - sx * pa[kz], ay = pa[ky] - sy * pa[kz];
  const float bx = pb[kx] - sx * pb[kz], by = pb[ky] - sy * pb[kz];
  const float cx = pc[kx] - sx * pc[kz], cy = pc[ky] - sy * pc[kz];
  // In double, where a product of two floats is exact, so each function's sign and its zero are
  // exact, and the same for every triangle on the edge (the paper falls back to double only at 0).
  const double u = static_cast<double>(cx) * by - static_cast<double>(cy) * bx;
  const double v = static_cast<double>(ax) * cy - static_cast<double>(ay) * cx;
  const double w = static_cast<double>(bx) * ay - static_cast<double>(by) * ax;
  if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;
  const double det = u + v + w;
  if (!(det != 0.0)) return false;
  // Near-degenerate triangles and rays in their plane, as before: t would be noise.
  const glm::vec3 e1 = b - a, e2 = c - a;
  const double scale = static_cast<double>(glm::dot(direction, direction)) * glm::dot(e1, e1) * glm::dot(e2, e2);
  const double sine = static_cast<double>(glm::dot(e1, glm::cross(direction, e2)));
  if (!(sine * sine > kParallelSine * kParallelSine * scale)) return false;
  // On an edge (its function 0): the triangle takes the ray only if it owns the edge.
  const bool behind = det < 0.0;
  const Sheared sa{ax, ay}, sb{bx, by}, sc{cx, cy};
  if (u == 0.0 && ownsEdge(sb, sc) == behind) return false;  // U: the edge b-c
  if (v == 0.0 && ownsEdge(sc, sa) == behind) return false;  // V: the edge c-a
  if (w == 0.0 && ownsEdge(sa, sb) == behind) return false;  // W: the edge a-b
  const double t = way * (u * (sz * pa[kz]) + v * (sz * pb[kz]) + w * (sz * pc[kz])) / det;
  if (!(t > tMin && t < tMax)) return false;
  tOut = static_cast<float>(t);
  return true;
}

// Per-ray constants for the box tests.
struct RaySetup {
  glm::vec3 origin;
  glm::vec3 direction;
  glm::vec3 inverse;  // 1 / direction; unused on axes where direction is 0
};

RaySetup setUp(const Ray& ray) {
  RaySetup r{ray.origin, ray.direction, glm::vec3(0.0f)};
  for (int i = 0; i < 3; ++i) {
    if (ray.direction[i] != 0.0f) r.inverse[i] = 1.0f / ray.direction[i];
  }
  return r;
}

// Slab test against [min, max] clipped to [tNear, tFar]; returns the entry t, or NaN for a miss.
// Each exit is pushed out by 2 gamma(3) of itself (Ize, "Robust BVH ray traversal", 2013) so
// rounding cannot reject a box that a triangle on its face is hit through.
float enterBox(const RaySetup& r, const glm::vec3& min, const glm::vec3& max, float tNear, float tFar) {
  constexpr float kEps = std::numeric_limits<float>::epsilon() * 0.5f;
  constexpr float kWiden = 2.0f * (3.0f * kEps / (1.0f - 3.0f * kEps));
  for (int i = 0; i < 3; ++i) {
    if (r.direction[i] == 0.0f) {
      // Parallel to this slab (1/0 would give 0 * inf = NaN for an origin on a face).
      if (r.origin[i] < min[i] || r.origin[i] > max[i]) return std::numeric_limits<float>::quiet_NaN();
      continue;
    }
    float t0 = (min[i] - r.origin[i]) * r.inverse[i];
    float t1 = (max[i] - r.origin[i]) * r.inverse[i];
    if (t0 > t1) std::swap(t0, t1);
    tNear = std::max(tNear, t0);
    tFar = std::min(tFar, t1 + kWiden * std::abs(t1));  // abs: tMin may be negative
  }
  return tNear <= tFar ? tNear : std::numeric_limits<float>::quiet_NaN();
}

}  // namespace

std::optional<float> intersectTriangle(const Ray& ray, const glm::vec3& a, const glm::vec3& b,
                                       const glm::vec3& c, float tMin, float tMax) {
  float t = 0.0f;
  if (hitTriangle(ray.origin, ray.direction, a, b, c, tMin, tMax, t)) return t;
  return std::nullopt;
}

namespace {

struct BuildInput {
  std::vector<glm::vec3> centroid;
  std::vector<glm::vec3> lo, hi;  // per-triangle bounds
};

// Appends the subtree over order[begin, end) and returns its node index. Median splits
// halve the count every level, so this terminates even when all centroids coincide.
// (A template only because the node type is private to RayScene.)
template <typename Node>
std::uint32_t buildNode(std::vector<Node>& nodes, std::vector<std::uint32_t>& order, const BuildInput& in,
                        std::uint32_t begin, std::uint32_t end) {
  const auto index = static_cast<std::uint32_t>(nodes.size());
  nodes.emplace_back();
  glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
  glm::vec3 centroidLo = lo, centroidHi = hi;
  for (std::uint32_t k = begin; k < end; ++k) {
    lo = glm::min(lo, in.lo[order[k]]);
    hi = glm::max(hi, in.hi[order[k]]);
    centroidLo = glm::min(centroidLo, in.centroid[order[k]]);
    centroidHi = glm::max(centroidHi, in.centroid[order[k]]);
  }
  nodes[index].min = lo;
  nodes[index].max = hi;
  if (end - begin <= kLeafSize) {
    nodes[index].first = begin;
    nodes[index].count = end - begin;
    return index;
  }
  const glm::vec3 spread = centroidHi - centroidLo;
  const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : (spread.y >= spread.z ? 1 : 2);
  const std::uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(
      order.begin() + begin, order.begin() + middle, order.begin() + end,
      [&](std::uint32_t x, std::uint32_t y) { return in.centroid[x][axis] < in.centroid[y][axis]; });
  buildNode(nodes, order, in, begin, middle);  // lands at index + 1
  const std::uint32_t right = buildNode(nodes, order, in, middle, end);
  nodes[index].first = right;  // after the recursion: emplace_back may have moved nodes
  return index;
}

}  // namespace

int RayScene::add(const Mesh& mesh, const glm::mat4& model) {
  validateMesh(mesh);
  if (const auto bad = firstNonFiniteVertex(mesh)) {
    throw std::invalid_argument("RayScene::add: vertex " + std::to_string(*bad) + " is not finite");
  }
  // transformed() checks the matrix and flips the winding of mirrored meshes.
  const Mesh world = transformed(mesh, model);
  if (const auto bad = firstNonFiniteVertex(world)) {
    throw std::invalid_argument("RayScene::add: vertex " + std::to_string(*bad) +
                                " is not finite after the model transform");
  }
  const std::size_t triangles = world.triangleCount();
  if (triangles > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max() / 3)) {
    throw std::invalid_argument("RayScene::add: too many triangles (" + std::to_string(triangles) + ")");
  }

  BuildInput in;
  in.centroid.resize(triangles);
  in.lo.resize(triangles);
  in.hi.resize(triangles);
  for (std::size_t t = 0; t < triangles; ++t) {
    const glm::vec3& a = world.positions[world.indices[3 * t]];
    const glm::vec3& b = world.positions[world.indices[3 * t + 1]];
    const glm::vec3& c = world.positions[world.indices[3 * t + 2]];
    in.centroid[t] = (a + b + c) / 3.0f;
    in.lo[t] = glm::min(a, glm::min(b, c));
    in.hi[t] = glm::max(a, glm::max(b, c));
  }
  std::vector<std::uint32_t> order(triangles);
  for (std::size_t t = 0; t < triangles; ++t) order[t] = static_cast<std::uint32_t>(t);

  Object object;
  if (triangles > 0) {
    object.nodes.reserve(2 * triangles / kLeafSize + 1);
    buildNode(object.nodes, order, in, 0, static_cast<std::uint32_t>(triangles));
  }
  // Corners stored in leaf order so a leaf reads one contiguous run.
  object.corners.reserve(3 * triangles);
  object.triangle.reserve(triangles);
  for (const std::uint32_t t : order) {
    for (int k = 0; k < 3; ++k) object.corners.push_back(world.positions[world.indices[3 * t + k]]);
    object.triangle.push_back(static_cast<std::int32_t>(t));
  }
  objects_.push_back(std::move(object));
  return static_cast<int>(objects_.size() - 1);
}

namespace {

// Walks one object's hierarchy nearer child first. With anyHit it returns at the first
// triangle hit; otherwise it shrinks tMax to each hit so farther boxes are skipped.
// Returns the slot hit (or -1) and leaves its t in tMax. A template for the same reason as buildNode.
template <typename Node>
int traverse(const std::vector<Node>& nodes, const std::vector<glm::vec3>& corners, const RaySetup& r,
             float tMin, float& tMax, bool anyHit) {
  if (nodes.empty()) return -1;
  const float rootEntry = enterBox(r, nodes[0].min, nodes[0].max, tMin, tMax);
  if (std::isnan(rootEntry)) return -1;
  // Median splits keep the depth under 32 for any triangle count add() accepts, and the
  // stack holds at most one waiting sibling per level.
  std::array<std::pair<std::uint32_t, float>, 64> stack;
  std::size_t size = 0;
  stack[size++] = {0u, rootEntry};
  int hitSlot = -1;
  while (size > 0) {
    const auto [index, entry] = stack[--size];
    if (entry > tMax) continue;  // a nearer hit was found since this box was pushed
    const Node& node = nodes[index];
    if (node.count > 0) {
      for (std::uint32_t slot = node.first; slot < node.first + node.count; ++slot) {
        float t = 0.0f;
        if (hitTriangle(r.origin, r.direction, corners[3 * slot], corners[3 * slot + 1],
                        corners[3 * slot + 2], tMin, tMax, t)) {
          tMax = t;
          hitSlot = static_cast<int>(slot);
          if (anyHit) return hitSlot;
        }
      }
      continue;
    }
    const std::uint32_t left = index + 1;
    const std::uint32_t right = node.first;
    const float leftEntry = enterBox(r, nodes[left].min, nodes[left].max, tMin, tMax);
    const float rightEntry = enterBox(r, nodes[right].min, nodes[right].max, tMin, tMax);
    const bool leftHit = !std::isnan(leftEntry), rightHit = !std::isnan(rightEntry);
    // Push the farther one first so the nearer one is popped next.
    if (leftHit && rightHit) {
      if (leftEntry <= rightEntry) {
        stack[size++] = {right, rightEntry};
        stack[size++] = {left, leftEntry};
      } else {
        stack[size++] = {left, leftEntry};
        stack[size++] = {right, rightEntry};
      }
    } else if (leftHit) {
      stack[size++] = {left, leftEntry};
    } else if (rightHit) {
      stack[size++] = {right, rightEntry};
    }
  }
  return hitSlot;
}

}  // namespace

std::optional<RayHit> RayScene::firstHit(const Ray& ray, float tMin, float tMax) const {
  const RaySetup r = setUp(ray);
  std::optional<RayHit> best;
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    const Object& object = objects_[o];
    const int slot = traverse(object.nodes, object.corners, r, tMin, tMax, false);
    if (slot < 0) continue;
    const glm::vec3* c = &object.corners[3 * static_cast<std::size_t>(slot)];
    // Non-degenerate, or it could not have been hit, so the normal is well defined.
    const glm::vec3 normal = glm::normalize(glm::cross(c[1] - c[0], c[2] - c[0]));
    best = RayHit{tMax, static_cast<int>(o), object.triangle[slot], normal};
  }
  return best;
}

bool RayScene::occluded(const Ray& ray, float tMin, float tMax, const std::function<bool(int)>& casts) const {
  const RaySetup r = setUp(ray);
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    if (casts && !casts(static_cast<int>(o))) continue;
    float limit = tMax;
    if (traverse(objects_[o].nodes, objects_[o].corners, r, tMin, limit, true) >= 0) return true;
  }
  return false;
}

std::vector<RayHit> RayScene::allHits(const Ray& ray, float tMin, float tMax) const {
  const RaySetup r = setUp(ray);
  std::vector<RayHit> hits;
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    const Object& object = objects_[o];
    if (object.nodes.empty() || std::isnan(enterBox(r, object.nodes[0].min, object.nodes[0].max, tMin, tMax)))
      continue;
    std::array<std::uint32_t, 64> stack;  // one waiting sibling per level, as in traverse
    std::size_t size = 0;
    stack[size++] = 0u;
    while (size > 0) {
      const std::uint32_t index = stack[--size];
      const auto& node = object.nodes[index];
      if (node.count > 0) {
        for (std::uint32_t slot = node.first; slot < node.first + node.count; ++slot) {
          const glm::vec3* c = &object.corners[3 * static_cast<std::size_t>(slot)];
          float t = 0.0f;
          if (hitTriangle(r.origin, r.direction, c[0], c[1], c[2], tMin, tMax, t))
            hits.push_back({t, static_cast<int>(o), object.triangle[slot],
                            glm::normalize(glm::cross(c[1] - c[0], c[2] - c[0]))});
        }
        continue;
      }
      for (const std::uint32_t child : {index + 1, node.first})  // the left child follows its parent
        if (!std::isnan(enterBox(r, object.nodes[child].min, object.nodes[child].max, tMin, tMax)))
          stack[size++] = child;
    }
  }
  return hits;
}

std::size_t RayScene::objectCount() const {
  return objects_.size();
}

std::optional<float> intersectSphere(const Ray& ray, const glm::vec3& centre, float radius, float tMin,
                                     float tMax) {
  // |o + t d - c|^2 = r^2: a t^2 + 2 b t + k = 0.
  const glm::dvec3 d(ray.direction), oc = glm::dvec3(ray.origin) - glm::dvec3(centre);
  const double a = glm::dot(d, d), b = glm::dot(oc, d), k = glm::dot(oc, oc) - double(radius) * radius;
  const double discriminant = b * b - a * k;
  if (!(a > 0.0) || !(discriminant >= 0.0)) return std::nullopt;
  const double root = std::sqrt(discriminant);
  for (const double t : {(-b - root) / a, (-b + root) / a})
    if (t > tMin && t < tMax) return static_cast<float>(t);
  return std::nullopt;
}

LightRay rayTowardsLight(const glm::vec3& point, const glm::vec4& light) {
  if (!std::isfinite(light.x) || !std::isfinite(light.y) || !std::isfinite(light.z) ||
      !std::isfinite(light.w)) {
    throw std::invalid_argument("rayTowardsLight: the light is not finite");
  }
  if (light.w == 0.0f) {
    const glm::vec3 direction(light);
    if (direction == glm::vec3(0.0f)) {
      throw std::invalid_argument("rayTowardsLight: a directional light needs a non-zero direction");
    }
    return {{point, direction}, INFINITY};
  }
  // t = 1 lands on the light itself.
  return {{point, glm::vec3(light) / light.w - point}, 1.0f};
}

CameraRay cameraRay(const glm::dmat4& inverseViewProjection, glm::ivec2 size, int x, int yTop) {
  const double ndcX = (x + 0.5) / size.x * 2.0 - 1.0;
  const double ndcY = 1.0 - (yTop + 0.5) / size.y * 2.0;
  const glm::dvec4 nearPoint = inverseViewProjection * glm::dvec4(ndcX, ndcY, -1.0, 1.0);
  const glm::dvec4 farPoint = inverseViewProjection * glm::dvec4(ndcX, ndcY, 1.0, 1.0);
  const glm::dvec3 a = glm::dvec3(nearPoint) / nearPoint.w;
  if (std::abs(farPoint.w) > 1e-9 * std::abs(nearPoint.w)) {
    const glm::dvec3 b = glm::dvec3(farPoint) / farPoint.w;
    return {{glm::vec3(a), glm::vec3(b - a)}, 1.0f};
  }
  const glm::dvec4 middle = inverseViewProjection * glm::dvec4(ndcX, ndcY, 0.0, 1.0);
  return {{glm::vec3(a), glm::vec3(glm::dvec3(middle) / middle.w - a)},
          std::numeric_limits<float>::infinity()};
}

}  // namespace stencil
