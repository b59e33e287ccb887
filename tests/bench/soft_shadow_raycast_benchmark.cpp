// How fast the oracle's ray caster (geometry/raycast.h) answers shadow rays in lesson 10's scene:
// the ground, the slab and the ball, shadow rays from ground points to samples of the area light.
// A converged ray-cast reference needs thousands of samples per receiver pixel; the rays per
// second say how long that takes (docs/10-soft-shadows.md).
#include <benchmark/benchmark.h>

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/raycast.h"
#include "geometry/shapes.h"
#include "geometry/soft_shadow.h"

using namespace stencil;

static void ShadowRaysToAreaLight(benchmark::State& state) {
  RayScene scene;
  scene.add(makePlane(3.0f, 12), glm::mat4(1.0f));
  scene.add(makeCube(0.5f),
            glm::scale(glm::translate(glm::mat4(1.0f), {-0.15f, 1.2f, 0.1f}), {1.2f, 0.02f, 1.2f}));
  scene.add(makeSphere(0.3f, 24, 12), glm::translate(glm::mat4(1.0f), {0.35f, 2.3f, 0.45f}));
  const AreaLight light{{0.0f, 4.0f, 0.0f}, {1.5f, 1.0f}, LightShape::Rectangle};
  const std::vector<glm::vec2> samples = unitSquareSamples(SamplePattern::Halton, 1024);
  std::size_t rays = 0, blocked = 0, k = 0;
  for (auto _ : state) {
    // Ground points on a 64 x 64 grid over the slab's shadow and around it.
    const glm::vec3 p(-1.5f + 3.0f * static_cast<float>(k % 64) / 63.0f, 0.0f,
                      -1.5f + 3.0f * static_cast<float>((k / 64) % 64) / 63.0f);
    const glm::vec3 q = lightPoint(light, samples[k % samples.size()]);
    const LightRay r = rayTowardsLight(p, glm::vec4(q, 1.0f));
    blocked += scene.occluded(r.ray, 1e-4f, r.tMax);
    ++rays;
    ++k;
  }
  benchmark::DoNotOptimize(blocked);
  state.counters["rays_per_second"] =
      benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
}
BENCHMARK(ShadowRaysToAreaLight);

BENCHMARK_MAIN();
