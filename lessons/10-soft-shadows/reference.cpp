// Lesson 10's exact answers, which the lights' pictures are judged by: the visible fraction of the
// area light past the slab in closed form (geometry/soft_shadow.h), the same fraction past any
// casters by a converged ray cast (geometry/soft_shadow_reference.h, on Embree where it is
// installed), and the penumbra's width measured on a picture beside W h / (H - h).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "geometry/soft_shadow_reference.h"
#include "soft_shadows.h"

namespace stencil::soft_shadows {
namespace {

// Whether origin + s direction meets the box for some s in [0, t).
bool rayHitsBox(glm::dvec3 origin, glm::dvec3 direction, double t, glm::dvec3 lo, glm::dvec3 hi) {
  double t0 = 0.0, t1 = t;
  for (int k = 0; k < 3; ++k) {
    if (direction[k] == 0.0) {
      if (origin[k] < lo[k] || origin[k] > hi[k]) return false;
      continue;
    }
    double ta = (lo[k] - origin[k]) / direction[k], tb = (hi[k] - origin[k]) / direction[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 >= t1) return false;
  }
  return true;
}

}  // namespace

// ---- the exact answer --------------------------------------------------------------------------

// Per pixel centre: the eye ray onto the ground (if the slab does not hide it) and the ground
// point's visible fraction of the area light (geometry/soft_shadow.h), written into the target.
void SoftShadows::drawReference(Frame& f, const AreaLight& area, const glm::mat4& viewProjection) {
  const glm::mat4 inverse = glm::inverse(viewProjection);
  const glm::vec3 lo = kSlabCentre - 0.5f * glm::vec3(kSlabSide, kSlabThickness, kSlabSide);
  const glm::vec3 hi = kSlabCentre + 0.5f * glm::vec3(kSlabSide, kSlabThickness, kSlabSide);
  std::vector<glm::vec3> corners;
  for (int i = 0; i < 8; ++i)
    corners.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
  const float n = static_cast<float>(f.option("lights"));
  // What the ambient pass left (the background, the casters) stays; ground pixels are replaced.
  std::vector<float> pixels(static_cast<std::size_t>(4 * f.size.x * f.size.y), 0.0f);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target_->fbo());
  glReadPixels(0, 0, f.size.x, f.size.y, GL_RGBA, GL_FLOAT, pixels.data());
  for (int y = 0; y < f.size.y; ++y)
    for (int x = 0; x < f.size.x; ++x) {
      const glm::vec2 ndc(2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(f.size.x) - 1.0f,
                          2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(f.size.y) - 1.0f);
      const glm::vec4 a = inverse * glm::vec4(ndc, -1.0f, 1.0f), b = inverse * glm::vec4(ndc, 0.0f, 1.0f);
      const glm::dvec3 origin = glm::dvec3(glm::vec3(a) / a.w);
      const glm::dvec3 direction = glm::dvec3(glm::vec3(b) / b.w) - origin;
      if (direction.y >= 0.0) continue;
      const double t = -origin.y / direction.y;
      const glm::dvec3 p = origin + t * direction;
      if (std::abs(p.x) > kGroundHalf || std::abs(p.z) > kGroundHalf) continue;
      if (rayHitsBox(origin, direction, t, glm::dvec3(lo), glm::dvec3(hi))) continue;
      const float v = static_cast<float>(visibleFraction(area, corners, glm::vec3(p)));
      float* px = &pixels[static_cast<std::size_t>(4 * (y * f.size.x + x))];
      px[0] = px[1] = px[2] = v;
      px[3] = v * n;
    }
  glBindTexture(GL_TEXTURE_2D, target_->colour());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, f.size.x, f.size.y, GL_RGBA, GL_FLOAT, pixels.data());
  endPass(f, "illumination");
}

// The same picture for any casters: per pixel, the eye ray's first hit and, where that is a
// receiver, the fraction of 2^converged stratified shadow rays to the light that nothing blocks
// (geometry/soft_shadow_reference.h, through occlusionBackend()).
void SoftShadows::drawConverged(Frame& f, const std::vector<Object>& scene, const AreaLight& area,
                                const glm::mat4& viewProjection) {
  OcclusionScene rays;
  std::vector<bool> receives;
  for (const Object& o : scene) {
    rays.add(*o.mesh, o.model);
    receives.push_back(!o.caster);
  }
  const int k = 1 << f.option("converged");
  f.count("reference_rays_per_pixel", static_cast<std::uint64_t>(k));
  const std::vector<float> fraction = convergedVisibility(
      rays, [&](int object) { return receives[static_cast<std::size_t>(object)]; }, area,
      glm::inverse(viewProjection), f.size, k, 0,
      [&](std::size_t done, std::size_t total) { f.progress("pixels ray cast", done, total); });
  const float n = static_cast<float>(f.option("lights"));
  std::vector<float> pixels(static_cast<std::size_t>(4 * f.size.x * f.size.y), 0.0f);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target_->fbo());
  glReadPixels(0, 0, f.size.x, f.size.y, GL_RGBA, GL_FLOAT, pixels.data());
  for (std::size_t i = 0; i < fraction.size(); ++i) {
    if (fraction[i] < 0.0f) continue;  // the background and the casters stay as the ambient pass left them
    float* px = &pixels[4 * i];
    px[0] = px[1] = px[2] = fraction[i];
    px[3] = fraction[i] * n;
  }
  glBindTexture(GL_TEXTURE_2D, target_->colour());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, f.size.x, f.size.y, GL_RGBA, GL_FLOAT, pixels.data());
  endPass(f, "illumination");
}

// ---- the penumbra's width, measured on the picture ------------------------------------------

// Where the picture is the visible fraction of a rectangular light past the slab alone: walk
// out of the slab's shadow across its +x edge (along the ground line z = the slab's centre) and
// across its +z edge (x = the slab's centre), reading the picture at each ground point's pixel,
// and time the ramp from 2% to 98% of the light; over 0.96 it is the whole ramp's width. Reported
// in thousandths of a unit beside W h / (H - h) for the slab's mid-plane h
// (geometry/soft_shadow.h's straightEdgePenumbraWidth).
void SoftShadows::measurePenumbra(Frame& f, const Target& picture, const AreaLight& area) {
  if (!(f.on("visibility") || f.on("reference")) || f.on("disk") || f.option("casters") != 1 ||
      f.option("size") == 0)
    return;
  std::vector<float> pixels(static_cast<std::size_t>(4 * f.size.x * f.size.y));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, picture.fbo());
  glReadPixels(0, 0, f.size.x, f.size.y, GL_RGBA, GL_FLOAT, pixels.data());
  const glm::mat4 viewProjection = f.projection * f.view;
  auto rampWidth = [&](glm::vec3 from, glm::vec3 step) {
    float at02 = -1.0f, at98 = -1.0f;
    for (int k = 0; k < 400; ++k) {
      const glm::vec3 p = from + static_cast<float>(k) * step;
      const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
      const glm::vec2 window = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(f.size);
      const int x = static_cast<int>(window.x), y = static_cast<int>(window.y);
      if (x < 0 || y < 0 || x >= f.size.x || y >= f.size.y) continue;
      const float v = pixels[static_cast<std::size_t>(4 * (y * f.size.x + x))];
      const float s = static_cast<float>(k) * glm::length(step);
      if (at02 < 0.0f && v >= 0.02f) at02 = s;
      if (at98 < 0.0f && v >= 0.98f) at98 = s;
    }
    return at02 < 0.0f || at98 < 0.0f ? 0.0 : static_cast<double>(at98 - at02) / 0.96;
  };
  const double H = kLightHeight, h = kSlabHeight;
  // From under the slab's middle outwards, 2 units in steps of 0.005.
  const double wx = rampWidth({kSlabCentre.x, 0.0f, kSlabCentre.z}, {0.005f, 0.0f, 0.0f});
  const double wz = rampWidth({kSlabCentre.x, 0.0f, kSlabCentre.z}, {0.0f, 0.0f, 0.005f});
  f.count("penumbra_width_x_milli", static_cast<std::uint64_t>(std::lround(1000.0 * wx)));
  f.count("penumbra_width_z_milli", static_cast<std::uint64_t>(std::lround(1000.0 * wz)));
  f.count("penumbra_width_x_predicted_milli",
          static_cast<std::uint64_t>(std::lround(1000.0 * straightEdgePenumbraWidth(area.size.x, H, h))));
  f.count("penumbra_width_z_predicted_milli",
          static_cast<std::uint64_t>(std::lround(1000.0 * straightEdgePenumbraWidth(area.size.y, H, h))));
}

}  // namespace stencil::soft_shadows
