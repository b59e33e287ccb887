#include "geometry/soft_shadow_reference.h"

#include <algorithm>
#include <glm/vec4.hpp>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#ifdef STENCIL_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

namespace stencil {

struct OcclusionScene::Impl {
  RayScene rays;  // validates every mesh, and answers when Embree is absent
#ifdef STENCIL_HAVE_EMBREE
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
#endif
};

const char* occlusionBackend() {
#ifdef STENCIL_HAVE_EMBREE
  return "embree " RTC_VERSION_STRING;
#else
  return "raycast";
#endif
}

OcclusionScene::OcclusionScene() : impl_(std::make_unique<Impl>()) {
#ifdef STENCIL_HAVE_EMBREE
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) throw std::runtime_error("Embree: rtcNewDevice failed");
  impl_->scene = rtcNewScene(impl_->device);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);
  rtcCommitScene(impl_->scene);
#endif
}

OcclusionScene::~OcclusionScene() {
#ifdef STENCIL_HAVE_EMBREE
  rtcReleaseScene(impl_->scene);
  rtcReleaseDevice(impl_->device);
#endif
}

int OcclusionScene::add(const Mesh& mesh, const glm::mat4& model) {
  const int id = impl_->rays.add(mesh, model);  // throws first, leaving both scenes unchanged
#ifdef STENCIL_HAVE_EMBREE
  const Mesh world = transformed(mesh, model);
  RTCGeometry g = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                        3 * sizeof(float), world.positions.size()));
  for (std::size_t i = 0; i < world.positions.size(); ++i)
    for (int k = 0; k < 3; ++k) v[3 * i + k] = world.positions[i][k];
  auto* index = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), world.indices.size() / 3));
  std::copy(world.indices.begin(), world.indices.end(), index);
  rtcCommitGeometry(g);
  rtcAttachGeometryByID(impl_->scene, g, static_cast<unsigned>(id));
  rtcReleaseGeometry(g);
  rtcCommitScene(impl_->scene);
#endif
  return id;
}

bool OcclusionScene::occluded(const Ray& ray, float tMin, float tMax) const {
#ifdef STENCIL_HAVE_EMBREE
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r{};
  r.org_x = ray.origin.x, r.org_y = ray.origin.y, r.org_z = ray.origin.z;
  r.dir_x = ray.direction.x, r.dir_y = ray.direction.y, r.dir_z = ray.direction.z;
  r.tnear = tMin;
  r.tfar = tMax;
  r.mask = ~0u;
  rtcOccluded1(impl_->scene, &context, &r);
  return r.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
#else
  return impl_->rays.occluded(ray, tMin, tMax);
#endif
}

std::optional<std::pair<float, int>> OcclusionScene::firstHit(const Ray& ray, float tMin, float tMax) const {
#ifdef STENCIL_HAVE_EMBREE
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit h{};
  h.ray.org_x = ray.origin.x, h.ray.org_y = ray.origin.y, h.ray.org_z = ray.origin.z;
  h.ray.dir_x = ray.direction.x, h.ray.dir_y = ray.direction.y, h.ray.dir_z = ray.direction.z;
  h.ray.tnear = tMin;
  h.ray.tfar = tMax;
  h.ray.mask = ~0u;
  h.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &h);
  if (h.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  return std::pair{h.ray.tfar, static_cast<int>(h.hit.geomID)};
#else
  const auto hit = impl_->rays.firstHit(ray, tMin, tMax);
  if (!hit) return std::nullopt;
  return std::pair{hit->t, hit->object};
#endif
}

namespace {

// Runs body(i) for i in [0, n) on `threads` threads (0: the hardware's count), in interleaved
// blocks so neighbouring receivers (similar cost) spread over the threads.
// After each block, progress (when given) hears how many of the n are done, one call at a time.
void parallelFor(std::size_t n, int threads, const std::function<void(std::size_t)>& body,
                 const ReferenceProgress& progress = {}) {
  unsigned count =
      threads > 0 ? static_cast<unsigned>(threads) : std::max(1u, std::thread::hardware_concurrency());
  count = static_cast<unsigned>(std::min<std::size_t>(count, std::max<std::size_t>(n, 1)));
  constexpr std::size_t kBlock = 64;
  std::mutex reporting;
  std::size_t done = 0;
  const auto blocks = [&](unsigned t, unsigned stride) {
    for (std::size_t start = t * kBlock; start < n; start += stride * kBlock) {
      const std::size_t end = std::min(n, start + kBlock);
      for (std::size_t i = start; i < end; ++i) body(i);
      if (progress) {
        const std::lock_guard lock(reporting);
        done += end - start;
        progress(done, n);
      }
    }
  };
  if (count <= 1) {
    blocks(0, 1);
    return;
  }
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < count; ++t) pool.emplace_back([&, t] { blocks(t, count); });
  for (std::thread& th : pool) th.join();
}

float fractionAt(const OcclusionQuery& occluded, const AreaLight& light, const glm::vec3& p, int samples,
                 std::size_t index, float tMin) {
  const std::vector<glm::vec2> unit =
      unitSquareSamples(SamplePattern::Jittered, samples, static_cast<int>(index));
  int seen = 0;
  for (const glm::vec2& u : unit) {
    const Ray ray{p, lightPoint(light, u) - p};
    seen += !occluded(ray, tMin, 1.0f);
  }
  return static_cast<float>(seen) / static_cast<float>(samples);
}

}  // namespace

std::vector<float> convergedVisibleFraction(const OcclusionQuery& occluded, const AreaLight& light,
                                            const std::vector<glm::vec3>& receivers, int samples, int threads,
                                            float tMin) {
  if (samples < 1) throw std::invalid_argument("converged visible fraction: samples must be at least 1");
  std::vector<float> out(receivers.size());
  parallelFor(receivers.size(), threads,
              [&](std::size_t i) { out[i] = fractionAt(occluded, light, receivers[i], samples, i, tMin); });
  return out;
}

std::vector<float> convergedVisibleFraction(const OcclusionScene& scene, const AreaLight& light,
                                            const std::vector<glm::vec3>& receivers, int samples, int threads,
                                            float tMin) {
  return convergedVisibleFraction([&](const Ray& r, float a, float b) { return scene.occluded(r, a, b); },
                                  light, receivers, samples, threads, tMin);
}

std::vector<float> convergedVisibility(const OcclusionScene& scene, const std::function<bool(int)>& receives,
                                       const AreaLight& light, const glm::mat4& inverseViewProjection,
                                       glm::ivec2 size, int samples, int threads,
                                       const ReferenceProgress& progress) {
  if (size.x < 1 || size.y < 1)
    throw std::invalid_argument("converged visibility: image size " + std::to_string(size.x) + "x" +
                                std::to_string(size.y) + " is empty");
  if (samples < 1) throw std::invalid_argument("converged visibility: samples must be at least 1");
  const OcclusionQuery query = [&](const Ray& r, float a, float b) { return scene.occluded(r, a, b); };
  const std::size_t n = static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y);
  std::vector<float> out(n, -1.0f);
  parallelFor(n, threads, [&](std::size_t i) {
    const int x = static_cast<int>(i % static_cast<std::size_t>(size.x));
    const int y = static_cast<int>(i / static_cast<std::size_t>(size.x));
    const glm::vec2 ndc(2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(size.x) - 1.0f,
                        2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(size.y) - 1.0f);
    const glm::vec4 a = inverseViewProjection * glm::vec4(ndc, -1.0f, 1.0f);
    const glm::vec4 b = inverseViewProjection * glm::vec4(ndc, 0.0f, 1.0f);
    const Ray eye{glm::vec3(a) / a.w, glm::vec3(b) / b.w - glm::vec3(a) / a.w};
    const auto hit = scene.firstHit(eye);
    if (!hit || !receives(hit->second)) return;
    out[i] = fractionAt(query, light, eye.origin + hit->first * eye.direction, samples, i, 1e-4f);
  }, progress);
  return out;
}

}  // namespace stencil
