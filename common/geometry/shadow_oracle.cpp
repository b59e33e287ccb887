#include "geometry/shadow_oracle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/projection.h"
#include "geometry/raycast.h"
#include "geometry/shadow_volume.h"

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

// GL's least sub-pixel precision (GL_SUBPIXEL_BITS >= 4): how far from where it lies a conforming
// rasterizer may put a vertex, in pixels, along x and along y.
constexpr double kLeastSnap = 1.0 / 16.0;

// One side of a shadow volume: a possible silhouette edge a -> b extruded away from the light, in
// the plane with normal n (unnormalized), which holds a, b and the light (or its direction).
struct VolumeSide {
  glm::dvec3 a, b, n;
  // Its plane's window depth at pixel (x, yTop): depth + dx x + dy yTop (a plane's depth is affine
  // in the picture's coordinates).
  double depth = 0.0, dx = 0.0, dy = 0.0;
};

// Every caster's volume sides for the light (xyz / w, or the direction towards it where w = 0),
// in the frame the rays are cast in: world less `origin`. The edges are found as the lessons find
// them: facesLight on the welded mesh in the object's own space, then possibleSilhouetteEdges.
std::vector<VolumeSide> volumeSides(const std::vector<OracleObject>& objectsInWorld, const glm::vec4& worldLight,
                                    const glm::dvec3& origin, const glm::dvec4& light) {
  std::vector<VolumeSide> sides;
  for (const OracleObject& o : objectsInWorld) {
    if (!o.casts || !o.mesh) continue;
    const PreparedCaster caster = prepareCaster(*o.mesh);
    const std::vector<bool> lit = facesLight(caster.mesh, glm::inverse(o.model) * worldLight);
    const glm::dmat4 model(o.model);
    for (const SilhouetteEdge& e : possibleSilhouetteEdges(caster.adjacency, lit)) {
      const glm::dvec3 a = glm::dvec3(model * glm::dvec4(glm::dvec3(caster.mesh.positions[e.v0]), 1.0)) - origin;
      const glm::dvec3 b = glm::dvec3(model * glm::dvec4(glm::dvec3(caster.mesh.positions[e.v1]), 1.0)) - origin;
      const glm::dvec3 n = light.w != 0.0 ? glm::cross(a - glm::dvec3(light), b - glm::dvec3(light))
                                          : glm::cross(b - a, -glm::dvec3(light));
      if (glm::dot(n, n) > 0.0) sides.push_back({a, b, n});
    }
  }
  return sides;
}

// Whether x, a point of the side's plane, lies on the side: beyond the edge, seen from the light,
// and between the two rays from the light (or along its direction) through a and b.
bool onSide(const VolumeSide& s, const glm::dvec3& x, const glm::dvec4& light) {
  const double nn = glm::dot(s.n, s.n);
  if (light.w != 0.0) {  // x - L = alpha (a - L) + beta (b - L): alpha, beta >= 0, alpha + beta >= 1
    const glm::dvec3 l(light);
    const double alpha = glm::dot(glm::cross(x - l, s.b - l), s.n) / nn;
    const double beta = glm::dot(glm::cross(s.a - l, x - l), s.n) / nn;
    return alpha >= 0.0 && beta >= 0.0 && alpha + beta >= 1.0;
  }
  const glm::dvec3 away = -glm::dvec3(light);  // x - a = u (b - a) + s away: 0 <= u <= 1, s >= 0
  const double u = glm::dot(glm::cross(x - s.a, away), s.n) / nn;
  const double along = glm::dot(glm::cross(s.b - s.a, x - s.a), s.n) / nn;
  return u >= 0.0 && u <= 1.0 && along >= 0.0;
}

bool onEdge(const std::vector<PixelClass>& oracle, const std::vector<int>* surfaces, const std::vector<bool>* ties,
            glm::ivec2 size, int x, int y) {
  const auto i = static_cast<std::size_t>(y * size.x + x);
  if (ties && (*ties)[i]) return true;
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
                const std::vector<int>* surfaces, const std::vector<bool>* ties) {
  const auto n = static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y);
  if (oracle.size() != n || lit.size() != n || (surfaces && surfaces->size() != n) || (ties && ties->size() != n))
    throw std::invalid_argument("oracle comparison: the images have different sizes");
}

}  // namespace

std::vector<PixelClass> classifyPixels(const std::vector<OracleObject>& objectsInWorld,
                                       const glm::vec4& worldLight, const glm::mat4& viewProjection,
                                       glm::ivec2 size, float lightRadius, std::vector<int>* surfaces,
                                       std::vector<bool>* ties) {
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

  // For the ties, in double: each pixel's ray (cameraRay's, for a pixel off the picture too), the
  // window depth where it meets a plane (clip z / w: any affine map of it, GL's or the reversed
  // one, scales depths and their moves alike), and the volume sides with their planes' depths.
  const glm::dmat4 toClip = glm::dmat4(viewProjection) * from;
  const glm::dvec4 lightHere = light.w != 0.0f ? glm::dvec4(glm::dvec3(worldLight) / double(worldLight.w) -
                                                                 glm::dvec3(origin), 1.0)
                                               : glm::dvec4(glm::dvec3(worldLight), 0.0);
  const auto rayAt = [&](int x, int yTop) {
    const double ndcX = (x + 0.5) / size.x * 2.0 - 1.0, ndcY = 1.0 - (yTop + 0.5) / size.y * 2.0;
    const glm::dvec4 nearPoint = inverse * glm::dvec4(ndcX, ndcY, -1.0, 1.0);
    const glm::dvec4 middle = inverse * glm::dvec4(ndcX, ndcY, 0.0, 1.0);  // finite for Pinf too
    const glm::dvec3 o = glm::dvec3(nearPoint) / nearPoint.w;
    return std::pair{o, glm::dvec3(middle) / middle.w - o};
  };
  const auto depthOnPlane = [&](int x, int yTop, const glm::dvec3& q, const glm::dvec3& n) {
    const auto [o, d] = rayAt(x, yTop);
    const glm::dvec4 c = toClip * glm::dvec4(o + glm::dot(n, q - o) / glm::dot(n, d) * d, 1.0);
    return c.z / c.w;
  };
  std::vector<VolumeSide> sides =
      ties ? volumeSides(objectsInWorld, worldLight, glm::dvec3(origin), lightHere) : std::vector<VolumeSide>{};
  for (VolumeSide& side : sides) {  // a plane's depth is affine in the picture's x and y
    side.depth = depthOnPlane(0, 0, side.a, side.n);
    side.dx = depthOnPlane(1, 0, side.a, side.n) - side.depth;
    side.dy = depthOnPlane(0, 1, side.a, side.n) - side.depth;
  }
  std::erase_if(sides, [](const VolumeSide& s) {  // a plane through the eye: a line in the picture
    return !std::isfinite(s.depth) || !std::isfinite(s.dx) || !std::isfinite(s.dy);
  });
  const auto tie = [&](int x, int yTop, const glm::vec3& hitPoint, const glm::vec3& normal) {
    // The surface's plane at this pixel, and how much its depth changes to the next pixel in x and y.
    const glm::dvec3 q(hitPoint), n(normal);
    const double surface = depthOnPlane(x, yTop, q, n);
    const double surfaceMoves = std::abs(depthOnPlane(x + 1, yTop, q, n) - surface) +
                                std::abs(depthOnPlane(x, yTop + 1, q, n) - surface);
    for (const VolumeSide& side : sides) {
      const double depth = side.depth + side.dx * x + side.dy * yTop;
      // Only the snapping: a depth buffer's rounding is the lesson's choice of buffer (its 24-bit
      // fallback is meant to show what that costs), and these doubles' own rounding is far below.
      const double rounding = 1e-12 * (1.0 + std::max(std::abs(depth), std::abs(surface)));
      if (std::abs(depth - surface) > kLeastSnap * (std::abs(side.dx) + std::abs(side.dy) + surfaceMoves) + rounding)
        continue;
      // Close enough in depth: a tie where the pixel's ray meets the side itself, not its plane.
      const auto [o, d] = rayAt(x, yTop);
      const double across = glm::dot(side.n, d);
      if (across == 0.0) continue;  // the side edge-on to the ray
      const double t = glm::dot(side.n, side.a - o) / across;
      if (t > 0.0 && onSide(side, o + t * d, lightHere)) return true;
    }
    return false;
  };

  std::vector<PixelClass> classes(static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y));
  if (surfaces) surfaces->assign(classes.size(), -1);
  if (ties) ties->assign(classes.size(), false);
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
      if (ties) (*ties)[static_cast<std::size_t>(y * size.x + x)] = tie(x, y, point, hit->normal);
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
                               glm::ivec2 size, const std::vector<int>* surfaces, const std::vector<bool>* ties) {
  checkSizes(oracle, litInImage, size, surfaces, ties);
  OracleReport report;
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const auto i = static_cast<std::size_t>(y * size.x + x);
      report.receiverPixels += oracle[i] == PixelClass::Lit || oracle[i] == PixelClass::Shadowed;
      report.shadowedPixels += oracle[i] == PixelClass::Shadowed;
      if ((oracle[i] == PixelClass::Lit) == litInImage[i]) continue;
      ++report.disagreements;
      report.onEdges += onEdge(oracle, surfaces, ties, size, x, y);
    }
  return report;
}

std::vector<bool> oracleEdges(const std::vector<PixelClass>& oracle, glm::ivec2 size,
                              const std::vector<int>* surfaces, const std::vector<bool>* ties) {
  checkSizes(oracle, std::vector<bool>(oracle.size()), size, surfaces, ties);
  std::vector<bool> edges(oracle.size());
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) edges[static_cast<std::size_t>(y * size.x + x)] = onEdge(oracle, surfaces, ties, size, x, y);
  return edges;
}

std::vector<std::uint8_t> oraclePicture(const std::vector<PixelClass>& oracle,
                                        const std::vector<bool>& litInImage, glm::ivec2 size,
                                        const std::vector<int>* surfaces, const std::vector<bool>* ties) {
  checkSizes(oracle, litInImage, size, surfaces, ties);
  std::vector<std::uint8_t> rgba;
  rgba.reserve(oracle.size() * 4);
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const auto i = static_cast<std::size_t>(y * size.x + x);
      glm::u8vec3 c;
      if ((oracle[i] == PixelClass::Lit) != litInImage[i])
        c = onEdge(oracle, surfaces, ties, size, x, y) ? glm::u8vec3(240, 200, 0) : glm::u8vec3(255, 0, 0);
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
