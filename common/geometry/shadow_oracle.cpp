#include "geometry/shadow_oracle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/projection.h"
#include "geometry/raycast.h"

namespace stencil {

namespace {

// |cos| of the light's incidence below which a surface is edge-on to the light: the light
// arrives at zero incidence, so lit and shadowed look the same and neither is claimed.
constexpr float kEdgeOn = 1e-5f;

// How far along the surface's normal a shadow ray starts so that it cannot meet the surface it
// starts on. The hit point carries the rounding of origin + t * direction in each coordinate, a
// few float ulps of the larger of the two (1e-6 is about 8 ulps); only the part along the normal
// can put the start behind the surface. Never less than 1e-4 scene units.
float selfIntersectionOffset(const glm::vec3& point, const glm::vec3& rayOrigin, const glm::vec3& normal) {
  const glm::vec3 error = 1e-6f * glm::max(glm::abs(point), glm::abs(rayOrigin));
  return std::max(1e-4f, glm::dot(glm::abs(normal), error));
}

bool onEdge(const std::vector<PixelClass>& oracle, const std::vector<int>* surfaces, glm::ivec2 size, int x,
            int y) {
  const auto i = static_cast<std::size_t>(y * size.x + x);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if (nx < 0 || ny < 0 || nx >= size.x || ny >= size.y) continue;
      const auto n = static_cast<std::size_t>(ny * size.x + nx);
      if (oracle[n] != oracle[i] || (surfaces && (*surfaces)[n] != (*surfaces)[i])) return true;
    }
  return false;
}

void checkSizes(const std::vector<PixelClass>& oracle, const std::vector<bool>& lit, glm::ivec2 size,
                const std::vector<int>* surfaces) {
  const auto n = static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y);
  if (oracle.size() != n || lit.size() != n || (surfaces && surfaces->size() != n))
    throw std::invalid_argument("oracle comparison: the images have different sizes");
}

}  // namespace

std::vector<PixelClass> classifyPixels(const std::vector<OracleObject>& objectsInWorld,
                                       const glm::vec4& worldLight, const glm::mat4& viewProjection,
                                       glm::ivec2 size, float lightRadius, std::vector<int>* surfaces) {
  // What a pixel sees and whether it is lit do not change when the objects, the camera and the
  // light move together. Cast from drawingOrigin near the eye (the centre of the near plane), so
  // that a ray's start and every hit carry rounding of their distance from the eye, as the pixel's
  // footprint does, not of their distance from the world's origin: 1e5 units out, rays that
  // started on the near plane rounded to float moved by 0.8 of a pixel at 1024x768.
  const glm::dvec4 nearCentre = glm::inverse(glm::dmat4(viewProjection)) * glm::dvec4(0.0, 0.0, -1.0, 1.0);
  const glm::vec3 origin = drawingOrigin(glm::vec3(glm::dvec3(nearCentre) / nearCentre.w));
  std::vector<OracleObject> objects = objectsInWorld;
  glm::vec4 light = worldLight;
  if (origin != glm::vec3(0.0f)) {  // else as given, bit for bit
    glm::dmat4 back(1.0);
    back[3] = glm::dvec4(-glm::dvec3(origin), 1.0);
    for (OracleObject& o : objects) {
      o.model = glm::mat4(back * glm::dmat4(o.model));
      if (o.sphere) o.sphere = glm::vec4(glm::vec3(*o.sphere) - origin, o.sphere->w);
    }
    if (light.w != 0.0f) light = glm::vec4(glm::vec3(light) / light.w - origin, 1.0f);
  }
  RayScene scene;
  std::vector<std::size_t> objectOf;  // scene object -> index into objects
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (objects[i].sphere) continue;
    scene.add(*objects[i].mesh, objects[i].model);
    objectOf.push_back(i);
  }
  const auto casts = [&](int object) { return objects[objectOf[static_cast<std::size_t>(object)]].casts; };
  struct Hit {
    float t;
    std::size_t object;
    glm::vec3 normal;
  };
  const auto firstHit = [&](const Ray& ray, float tMax) {
    std::optional<Hit> best;
    if (const auto h = scene.firstHit(ray, 0.0f, tMax))
      best = Hit{h->t, objectOf[static_cast<std::size_t>(h->object)], h->normal};
    for (std::size_t i = 0; i < objects.size(); ++i) {
      if (!objects[i].sphere) continue;
      const glm::vec4 s = *objects[i].sphere;
      if (const auto t = intersectSphere(ray, glm::vec3(s), s.w, 0.0f, best ? best->t : tMax))
        best = Hit{*t, i, glm::normalize(ray.origin + *t * ray.direction - glm::vec3(s))};
    }
    return best;
  };
  const auto occluded = [&](const LightRay& r) {
    if (scene.occluded(r.ray, 0.0f, r.tMax, casts)) return true;
    for (const OracleObject& o : objects)
      if (o.sphere && o.casts && intersectSphere(r.ray, glm::vec3(*o.sphere), o.sphere->w, 0.0f, r.tMax))
        return true;
    return false;
  };
  glm::dmat4 from(1.0);
  from[3] = glm::dvec4(glm::dvec3(origin), 1.0);
  const glm::dmat4 inverse = glm::inverse(glm::dmat4(viewProjection) * from);  // clip to (world - origin)

  std::vector<PixelClass> classes(static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y));
  if (surfaces) surfaces->assign(classes.size(), -1);
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      PixelClass& c = classes[static_cast<std::size_t>(y * size.x + x)];
      const auto [ray, tMax] = cameraRay(inverse, size, x, y);
      const auto hit = firstHit(ray, tMax);
      if (!hit) {
        c = PixelClass::Empty;
        continue;
      }
      if (surfaces) (*surfaces)[static_cast<std::size_t>(y * size.x + x)] = static_cast<int>(hit->object);
      if (!objects[hit->object].receives) {
        c = PixelClass::Other;
        continue;
      }
      // Start the shadow ray a hair off the surface, on the side the camera sees, so the
      // receiver does not shadow itself through rounding.
      const glm::vec3 point = ray.origin + hit->t * ray.direction;
      const glm::vec3 toLight = light.w == 0.0f ? glm::normalize(glm::vec3(light))
                                                : glm::normalize(glm::vec3(light) / light.w - point);
      const bool beyondRadius =
          light.w != 0.0f && glm::distance(point, glm::vec3(light) / light.w) > lightRadius;
      if (beyondRadius || std::abs(glm::dot(hit->normal, toLight)) < kEdgeOn) {
        c = PixelClass::OutOfReach;
        continue;
      }
      // The side of the surface the camera sees. A caster's side turned from the light lies in
      // its own shadow volume (between its light cap and its dark cap), which is where the
      // stencil puts it; deciding it by that rule, not by a shadow ray grazing the surface,
      // keeps facets a hair from edge-on from being called lit by rounding.
      const glm::vec3 towardsCamera =
          glm::dot(hit->normal, ray.direction) < 0.0f ? hit->normal : -hit->normal;
      if (objects[hit->object].casts && glm::dot(towardsCamera, toLight) < 0.0f) {
        c = PixelClass::Shadowed;
        // The other side of the caster's terminator: a surface of its own for the edge test.
        if (surfaces) (*surfaces)[static_cast<std::size_t>(y * size.x + x)] = static_cast<int>(hit->object + objects.size());
        continue;
      }
      c = occluded(rayTowardsLight(
              point + selfIntersectionOffset(point, ray.origin, towardsCamera) * towardsCamera, light))
              ? PixelClass::Shadowed
              : PixelClass::Lit;
    }
  return classes;
}

OracleReport compareWithOracle(const std::vector<PixelClass>& oracle, const std::vector<bool>& litInImage,
                               glm::ivec2 size, const std::vector<int>* surfaces) {
  checkSizes(oracle, litInImage, size, surfaces);
  OracleReport report;
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const auto i = static_cast<std::size_t>(y * size.x + x);
      report.receiverPixels += oracle[i] == PixelClass::Lit || oracle[i] == PixelClass::Shadowed;
      report.shadowedPixels += oracle[i] == PixelClass::Shadowed;
      if ((oracle[i] == PixelClass::Lit) == litInImage[i]) continue;
      ++report.disagreements;
      report.onEdges += onEdge(oracle, surfaces, size, x, y);
    }
  return report;
}

std::vector<std::uint8_t> oraclePicture(const std::vector<PixelClass>& oracle,
                                        const std::vector<bool>& litInImage, glm::ivec2 size,
                                        const std::vector<int>* surfaces) {
  checkSizes(oracle, litInImage, size, surfaces);
  std::vector<std::uint8_t> rgba;
  rgba.reserve(oracle.size() * 4);
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const auto i = static_cast<std::size_t>(y * size.x + x);
      glm::u8vec3 c;
      if ((oracle[i] == PixelClass::Lit) != litInImage[i])
        c = onEdge(oracle, surfaces, size, x, y) ? glm::u8vec3(240, 200, 0) : glm::u8vec3(255, 0, 0);
      else if (oracle[i] == PixelClass::Lit)
        c = {210, 210, 200};
      else if (oracle[i] == PixelClass::Shadowed)
        c = {40, 60, 140};
      else if (oracle[i] == PixelClass::Other)
        c = {110, 100, 90};
      else if (oracle[i] == PixelClass::OutOfReach)
        c = {60, 60, 60};
      else
        c = {0, 0, 0};
      rgba.insert(rgba.end(), {c.r, c.g, c.b, 255});
    }
  return rgba;
}

}  // namespace stencil
