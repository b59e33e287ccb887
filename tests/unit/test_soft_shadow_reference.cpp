// The converged soft-shadow reference (geometry/soft_shadow_reference.h) checked two ways: against
// the analytic visible fraction past lesson 10's slab (within the K^(-3/4) sampling error the
// header derives), and ray for ray against the oracle's own ray caster (geometry/raycast.h), with
// both casters' rays per second measured in the same run.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <iostream>

#include "geometry/shapes.h"
#include "geometry/soft_shadow_reference.h"

using namespace stencil;

namespace {

// Lesson 10's scene: the light 4 above the ground, the slab's mid-plane at 1.2, the ball above it.
constexpr glm::vec3 kSlabCentre{-0.15f, 1.2f, 0.1f};
constexpr glm::vec3 kSlabScale{1.2f, 0.02f, 1.2f};
const AreaLight kLight{{0.0f, 4.0f, 0.0f}, {1.5f, 1.0f}, LightShape::Rectangle};

glm::mat4 slabModel() {
  return glm::scale(glm::translate(glm::mat4(1.0f), kSlabCentre), kSlabScale);
}
glm::mat4 ballModel() {
  return glm::translate(glm::mat4(1.0f), {0.35f, 2.3f, 0.45f});
}

std::vector<glm::vec3> slabCorners() {
  const glm::vec3 lo = kSlabCentre - 0.5f * kSlabScale, hi = kSlabCentre + 0.5f * kSlabScale;
  std::vector<glm::vec3> c;
  for (int i = 0; i < 8; ++i) c.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
  return c;
}

// Ground points on an n x n grid over the slab's shadow and the penumbra around it.
std::vector<glm::vec3> groundGrid(int n) {
  std::vector<glm::vec3> points;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      points.push_back({-1.6f + 3.0f * (static_cast<float>(i) + 0.5f) / static_cast<float>(n), 0.0f,
                        -1.4f + 3.0f * (static_cast<float>(j) + 0.5f) / static_cast<float>(n)});
  return points;
}

}  // namespace

TEST(SoftShadowReference, AgreesWithTheAnalyticFractionPastTheSlab) {
  OcclusionScene scene;
  scene.add(makeCube(0.5f), slabModel());
  const std::vector<glm::vec3> points = groundGrid(48);
  const std::vector<glm::vec3> corners = slabCorners();
  for (int k : {256, 1024}) {
    const std::vector<float> estimate = convergedVisibleFraction(scene, kLight, points, k, 2);
    const double bound = std::pow(static_cast<double>(k), -0.75);  // the estimate's deviation at most
    double sum = 0.0, worst = 0.0;
    int penumbra = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double exact = visibleFraction(kLight, corners, points[i]);
      const double error = estimate[i] - exact;
      if (exact <= 0.0 || exact >= 1.0) {
        // Umbra and fully lit points: every sample agrees.
        EXPECT_NEAR(estimate[i], exact, 1e-6) << "point " << i;
        continue;
      }
      ++penumbra;
      sum += error * error;
      worst = std::max(worst, std::abs(error));
    }
    const double rms = std::sqrt(sum / penumbra);
    std::cout << "K = " << k << ": " << penumbra << " penumbra points, RMS " << rms << ", max " << worst
              << " (deviation bound " << bound << ")\n";
    ASSERT_GT(penumbra, 200);
    EXPECT_LT(rms, bound);
    EXPECT_LT(worst, 5.0 * bound);
  }
}

TEST(SoftShadowReference, SameRaysAsTheOraclesCasterAndFaster) {
  OcclusionScene scene;
  RayScene oracle;
  for (auto [mesh, model] :
       {std::pair{makeCube(0.5f), slabModel()}, std::pair{makeSphere(0.3f, 24, 12), ballModel()}}) {
    scene.add(mesh, model);
    oracle.add(mesh, model);
  }
  const std::vector<glm::vec3> points = groundGrid(64);
  constexpr int kSamples = 256;
  // Ray for ray on one thread: the same rays, the same answers.
  std::size_t rays = 0, differ = 0, blocked = 0;
  double embreeSeconds = 0.0, oracleSeconds = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::vector<glm::vec2> unit =
        unitSquareSamples(SamplePattern::Jittered, kSamples, static_cast<int>(i));
    std::vector<Ray> batch;
    for (const glm::vec2& u : unit) batch.push_back({points[i], lightPoint(kLight, u) - points[i]});
    std::vector<char> a(batch.size()), b(batch.size());
    auto t0 = std::chrono::steady_clock::now();
    for (std::size_t r = 0; r < batch.size(); ++r) a[r] = scene.occluded(batch[r], 1e-4f, 1.0f);
    auto t1 = std::chrono::steady_clock::now();
    for (std::size_t r = 0; r < batch.size(); ++r) b[r] = oracle.occluded(batch[r], 1e-4f, 1.0f);
    auto t2 = std::chrono::steady_clock::now();
    embreeSeconds += std::chrono::duration<double>(t1 - t0).count();
    oracleSeconds += std::chrono::duration<double>(t2 - t1).count();
    for (std::size_t r = 0; r < batch.size(); ++r) {
      differ += a[r] != b[r];
      blocked += b[r];
    }
    rays += batch.size();
  }
  std::cout << occlusionBackend() << ": " << static_cast<double>(rays) / embreeSeconds / 1e6
            << " M rays/s; raycast: " << static_cast<double>(rays) / oracleSeconds / 1e6
            << " M rays/s (one thread, " << rays << " rays, " << blocked << " blocked, " << differ
            << " answered differently)\n";
  EXPECT_GT(blocked, rays / 20);  // the rays do pass the casters
  EXPECT_EQ(differ, 0u);
  // The converged fraction through either caster is the same picture.
  const std::vector<float> viaScene = convergedVisibleFraction(scene, kLight, points, kSamples, 2);
  const std::vector<float> viaOracle = convergedVisibleFraction(
      [&](const Ray& r, float a, float b) { return oracle.occluded(r, a, b); }, kLight, points, kSamples, 2);
  EXPECT_EQ(viaScene, viaOracle);
}

TEST(SoftShadowReference, PictureOfTheGroundFromAbove) {
  OcclusionScene scene;
  const int ground = scene.add(makePlane(3.0f, 12), glm::mat4(1.0f));
  scene.add(makeCube(0.5f), slabModel());
  // Looking straight down from above the light, the whole image a 4 x 4 square of ground.
  const glm::mat4 viewProjection =
      glm::ortho(-2.0f, 2.0f, -2.0f, 2.0f, 0.1f, 20.0f) *
      glm::lookAt(glm::vec3(0.0f, 10.0f, 0.0f), glm::vec3(0.0f), {0.0f, 0.0f, -1.0f});
  const glm::ivec2 size(16, 16);
  const std::vector<float> picture = convergedVisibility(
      scene, [&](int object) { return object == ground; }, kLight, glm::inverse(viewProjection), size, 1024,
      2);
  ASSERT_EQ(picture.size(), 256u);
  int hidden = 0, lit = 0;
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const float v = picture[static_cast<std::size_t>(y * size.x + x)];
      // Pixel centre in world space (x right, -z up the image).
      const float u = (static_cast<float>(x) + 0.5f) / 16.0f, w = (static_cast<float>(y) + 0.5f) / 16.0f;
      const glm::vec3 p(-2.0f + 4.0f * u, 0.0f, 2.0f - 4.0f * w);
      const bool underSlab = std::abs(p.x - kSlabCentre.x) < 0.6f && std::abs(p.z - kSlabCentre.z) < 0.6f;
      if (underSlab) {
        EXPECT_EQ(v, -1.0f) << x << ", " << y;  // the slab is the first hit: not a receiver
        ++hidden;
        continue;
      }
      if (std::abs(p.x - kSlabCentre.x) > 0.65f || std::abs(p.z - kSlabCentre.z) > 0.65f) {
        // Within 5 deviations of K = 1024 (5 * 1024^(-3/4) = 0.028).
        EXPECT_NEAR(v, visibleFraction(kLight, slabCorners(), p), 0.028) << x << ", " << y;
        lit += v == 1.0f;
      }
    }
  EXPECT_GT(hidden, 0);
  EXPECT_GT(lit, 0);
  EXPECT_THROW(convergedVisibility(scene, {}, kLight, glm::mat4(1.0f), {0, 4}, 16), std::invalid_argument);
  EXPECT_THROW(convergedVisibility(
                   scene, [](int) { return true; }, kLight, glm::mat4(1.0f), {4, 4}, 0),
               std::invalid_argument);
  EXPECT_THROW(convergedVisibleFraction(scene, kLight, {}, 0), std::invalid_argument);
}
