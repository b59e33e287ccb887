// A converged reference for soft shadows from an area light, for any scene: the visible fraction
// of the light (geometry/soft_shadow.h) estimated by casting shadow rays to K stratified samples
// of the light per receiver point, K in the thousands (Cook, Porter and Carpenter 1984,
// "Distributed Ray Tracing"). Where the analytic visibleFraction covers one convex caster over a
// plane, this covers every caster, curved ones included, with a sampling error it can state: a
// convex occluder's projection onto the light cuts at most 4 sqrt(K) of the sqrt(K) x sqrt(K)
// strata (it crosses each row and each column of cells at most twice), each cut stratum a
// Bernoulli draw of variance at most 1/4 and the others exact, so the estimate's standard
// deviation is at most sqrt(4 sqrt(K) / 4) / K = K^(-3/4) (0.0055 at K = 1024, 0.0020 at 4096).
//
// Occlusion queries go to Embree (libembree-dev, embree 3) when the build found it, else to the
// oracle's own ray caster (geometry/raycast.h); occlusionBackend() says which. No OpenGL.
#pragma once
#include <cmath>
#include <functional>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "geometry/mesh.h"
#include "geometry/raycast.h"
#include "geometry/soft_shadow.h"

namespace stencil {

// "embree 3.13.5" (the library's version) or "raycast" (RayScene, the fallback).
const char* occlusionBackend();

// Triangle meshes placed in world space for first-hit and any-hit queries, as RayScene's but
// through occlusionBackend(). Rays through an edge or a corner may be counted differently by
// Embree's watertight test and RayScene's Möller-Trumbore (counted in
// tests/unit/test_soft_shadow_reference.cpp).
class OcclusionScene {
 public:
  OcclusionScene();
  ~OcclusionScene();
  OcclusionScene(const OcclusionScene&) = delete;
  OcclusionScene& operator=(const OcclusionScene&) = delete;

  // The object id (0, 1, ...); throws std::invalid_argument as RayScene::add does (the scene is
  // unchanged then). Rebuilds the hierarchy: add every object before querying from threads.
  int add(const Mesh& mesh, const glm::mat4& model);

  // Any hit with t in (tMin, tMax) (any object).
  bool occluded(const Ray& ray, float tMin, float tMax) const;
  // The nearest hit with t in (tMin, tMax): its t and object id.
  std::optional<std::pair<float, int>> firstHit(const Ray& ray, float tMin = 0.0f,
                                                float tMax = INFINITY) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The visible fraction of `light` from each receiver point (world space), over K = samples
// stratified (Jittered) samples of the light: receiver i draws unitSquareSamples(Jittered, K, i)
// mapped by lightPoint, and casts the shadow ray p -> light point with t in (tMin, 1) (t in units
// of that segment; tMin keeps a surface from shadowing itself). `occluded(ray, tMin, tMax)`
// answers each ray; threads (0: the hardware's count) share the receivers. Result: one fraction
// in [0, 1] per receiver. Throws std::invalid_argument for samples < 1.
using OcclusionQuery = std::function<bool(const Ray&, float, float)>;
std::vector<float> convergedVisibleFraction(const OcclusionQuery& occluded, const AreaLight& light,
                                            const std::vector<glm::vec3>& receivers, int samples,
                                            int threads = 0, float tMin = 1e-4f);
std::vector<float> convergedVisibleFraction(const OcclusionScene& scene, const AreaLight& light,
                                            const std::vector<glm::vec3>& receivers, int samples,
                                            int threads = 0, float tMin = 1e-4f);

// The picture of it: per pixel centre of a size.x x size.y image (row 0 at the bottom, as
// glReadPixels), the camera ray from the near plane (NDC z = -1) through NDC z = 0 of
// inverseViewProjection; where its first hit is an object for which receives(object) is true,
// the visible fraction at that point (as above, receiver index = pixel index y * size.x + x),
// else -1. Throws std::invalid_argument for a size below 1 x 1 or samples < 1.
// progress, when given, is told how many pixels of the whole are done, from the worker threads,
// one call at a time, after each block of pixels.
using ReferenceProgress = std::function<void(std::size_t done, std::size_t total)>;
std::vector<float> convergedVisibility(const OcclusionScene& scene, const std::function<bool(int)>& receives,
                                       const AreaLight& light, const glm::mat4& inverseViewProjection,
                                       glm::ivec2 size, int samples, int threads = 0,
                                       const ReferenceProgress& progress = {});

}  // namespace stencil
