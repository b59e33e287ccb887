#include "geometry/fast_shadows.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stencil {
namespace {

constexpr double kPi = 3.14159265358979323846;  // <cmath>'s name for it is POSIX, not C++

}  // namespace

std::vector<glm::vec4> doubledVertexArray(const Mesh& welded) {
  std::vector<glm::vec4> vertices;
  vertices.reserve(2 * welded.positions.size());
  for (const glm::vec3& p : welded.positions) vertices.emplace_back(p, 1.0f);
  for (const glm::vec3& p : welded.positions) vertices.emplace_back(p, 0.0f);
  return vertices;
}

std::vector<std::uint32_t> sideIndices(const Mesh& welded, const std::vector<SilhouetteEdge>& edges,
                                       bool directional) {
  const auto n = static_cast<std::uint32_t>(welded.positions.size());
  std::vector<std::uint32_t> indices;
  indices.reserve(edges.size() * (directional ? 3 : 6));
  for (const SilhouetteEdge& e : edges) {
    if (directional) {  // both far copies are the one point at infinity: b, a, a' faces out
      indices.insert(indices.end(), {e.v1, e.v0, e.v0 + n});
      continue;
    }
    const std::uint32_t corner[4] = {e.v0, e.v1, e.v0 + n, e.v1 + n};
    for (int c : extrudedQuadCorners(welded.positions.at(e.v0), welded.positions.at(e.v1)))
      indices.push_back(corner[c]);
  }
  return indices;
}

std::vector<SilhouetteEdge> possibleSilhouetteEdges(const PreparedCaster& caster,
                                                    const std::vector<bool>& lit) {
  return caster.report.closedManifold() ? possibleSilhouetteEdges(caster.adjacency, lit)
                                        : twoSidedSilhouetteEdges(caster.adjacency, lit);
}

std::vector<SilhouetteEdge> twoSidedSilhouetteEdges(const EdgeAdjacency& adjacency,
                                                    const std::vector<bool>& lit) {
  std::vector<SilhouetteEdge> edges;
  for (const Edge& e : adjacency.edges) {
    const bool lit0 = lit.at(static_cast<std::size_t>(e.face0));
    if (e.face1 < 0) {  // face0 walks v0 -> v1; turned round when it faces away
      edges.push_back(lit0 ? SilhouetteEdge{e.v0, e.v1} : SilhouetteEdge{e.v1, e.v0});
      continue;
    }
    if (lit0 == lit.at(static_cast<std::size_t>(e.face1))) continue;
    const SilhouetteEdge walked = lit0 ? SilhouetteEdge{e.v0, e.v1} : SilhouetteEdge{e.v1, e.v0};
    edges.insert(edges.end(), {walked, walked});
  }
  return edges;
}

namespace {

// Triangle t's indices plus offset, as it is or turned round.
void addTriangle(std::vector<std::uint32_t>& indices, const Mesh& mesh, std::size_t t, std::uint32_t offset,
                 bool turned) {
  const std::uint32_t a = mesh.indices[3 * t] + offset, b = mesh.indices[3 * t + 1] + offset,
                      c = mesh.indices[3 * t + 2] + offset;
  if (turned)
    indices.insert(indices.end(), {a, c, b});
  else
    indices.insert(indices.end(), {a, b, c});
}

}  // namespace

std::vector<std::uint32_t> lightCapIndices(const Mesh& welded, const std::vector<bool>& lit, bool twoSided) {
  std::vector<std::uint32_t> indices;
  for (std::size_t t = 0; t < lit.size(); ++t)
    if (lit[t] || twoSided) addTriangle(indices, welded, t, 0, !lit[t]);
  return indices;
}

std::vector<std::uint32_t> backFaceDarkCapIndices(const Mesh& welded, const std::vector<bool>& lit,
                                                  bool twoSided) {
  const auto n = static_cast<std::uint32_t>(welded.positions.size());
  std::vector<std::uint32_t> indices;
  for (std::size_t t = 0; t < lit.size(); ++t)
    if (!lit[t] || twoSided) addTriangle(indices, welded, t, n, lit[t]);
  return indices;
}

std::vector<std::uint32_t> pieceDarkCapIndices(const Mesh& welded, const std::vector<bool>& lit) {
  const auto n = static_cast<std::uint32_t>(welded.positions.size());
  std::vector<std::uint32_t> indices;
  for (std::size_t t = 0; t < lit.size(); ++t)
    if (lit[t]) addTriangle(indices, welded, t, n, true);
  return indices;
}

float spanDegrees(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  if (glm::length(a) == 0.0f || glm::length(b) == 0.0f || glm::length(c) == 0.0f) return 180.0f;
  const glm::dvec3 u[3] = {glm::normalize(glm::dvec3(a)), glm::normalize(glm::dvec3(b)),
                           glm::normalize(glm::dvec3(c))};
  const auto angle = [](const glm::dvec3& p, const glm::dvec3& q) {
    return std::acos(std::clamp(glm::dot(p, q), -1.0, 1.0));
  };
  double best = kPi / 2;  // no cap smaller than a hemisphere: 180 degrees
  // A cap whose diameter is one pair's arc, when it holds the third direction.
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3 &p = u[i], &q = u[(i + 1) % 3], &r = u[(i + 2) % 3];
    const glm::dvec3 mid = p + q;
    if (glm::length(mid) < 1e-12) continue;  // antipodal: no short arc
    const glm::dvec3 m = glm::normalize(mid);
    const double radius = angle(p, m);
    if (angle(r, m) <= radius + 1e-9) best = std::min(best, radius);
  }
  // The circumscribed cap, on the side of the plane through the three tips that holds them.
  const glm::dvec3 normal = glm::cross(u[1] - u[0], u[2] - u[0]);
  if (glm::length(normal) > 1e-12) {
    glm::dvec3 m = glm::normalize(normal);
    if (glm::dot(m, u[0]) < 0.0) m = -m;
    if (glm::dot(m, u[0]) > 1e-12) best = std::min(best, angle(u[0], m));
  }
  return static_cast<float>(glm::degrees(2.0 * best));
}

DarkCap fanDarkCap(const Mesh& welded, const std::vector<SilhouetteEdge>& edges, const glm::vec3& light,
                   float splitDegrees) {
  DarkCap cap;
  if (edges.empty()) return cap;
  const auto n = static_cast<std::uint32_t>(welded.positions.size());
  const std::uint32_t apex = edges.front().v0;
  const glm::vec3& pc = welded.positions.at(apex);
  for (const SilhouetteEdge& e : edges) {
    if (e.v0 == apex || e.v1 == apex) continue;  // a triangle with no area
    const glm::vec3 &pa = welded.positions.at(e.v0), &pb = welded.positions.at(e.v1);
    if (spanDegrees(pc - light, pb - light, pa - light) < splitDegrees) {
      cap.indices.insert(cap.indices.end(), {apex + n, e.v1 + n, e.v0 + n});  // c, b, a: away from the light
      continue;
    }
    // Through the foot of the light on the triangle's plane: each piece has the foot's direction
    // as a corner and spans less. With the light in the plane, the side the triangle faces.
    ++cap.splitTriangles;
    const glm::vec3 normal = glm::cross(pb - pc, pa - pc);
    const float normalLength = glm::length(normal);
    if (normalLength == 0.0f) continue;  // a triangle of no area covers nothing
    const glm::vec3 unit = normal / normalLength;
    glm::vec3 foot = light - unit * glm::dot(unit, light - pc);
    if (glm::length(foot - light) < 1e-6f * (1.0f + glm::length(pc - light))) foot = light + unit;
    const glm::vec3 corners[3] = {pc, pb, pa};
    for (int k = 0; k < 3; ++k)
      cap.split.insert(cap.split.end(), {glm::vec4(corners[k], 0.0f), glm::vec4(corners[(k + 1) % 3], 0.0f),
                                         glm::vec4(foot, 0.0f)});
  }
  return cap;
}

double solidAngle(const glm::vec3& eye, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::dvec3 p = glm::dvec3(a) - glm::dvec3(eye), q = glm::dvec3(b) - glm::dvec3(eye),
                   r = glm::dvec3(c) - glm::dvec3(eye);
  const double lp = glm::length(p), lq = glm::length(q), lr = glm::length(r);
  const double numerator = glm::dot(p, glm::cross(q, r));
  const double denominator = lp * lq * lr + glm::dot(p, q) * lr + glm::dot(p, r) * lq + glm::dot(q, r) * lp;
  return 2.0 * std::atan2(numerator, denominator);
}

int closeAroundLight(DarkCap& cap, const Mesh& welded, const std::vector<std::uint32_t>& lightCap,
                     const glm::vec3& light) {
  const auto n = static_cast<std::uint32_t>(welded.positions.size());
  const auto at = [&](std::uint32_t i) { return welded.positions.at(i < n ? i : i - n); };
  double total = 0.0;
  const std::vector<std::uint32_t>* lists[] = {&lightCap, &cap.indices};
  for (const std::vector<std::uint32_t>* list : lists)
    for (std::size_t t = 0; t + 2 < list->size(); t += 3)
      total += solidAngle(light, at((*list)[t]), at((*list)[t + 1]), at((*list)[t + 2]));
  for (std::size_t t = 0; t + 2 < cap.split.size(); t += 3)
    total +=
        solidAngle(light, glm::vec3(cap.split[t]), glm::vec3(cap.split[t + 1]), glm::vec3(cap.split[t + 2]));
  const int spheres = static_cast<int>(std::lround(total / (4.0 * kPi)));
  // The octahedron of the six axis directions around the light, each face wound clockwise seen
  // from the light (facing away); turned round for spheres facing it.
  const glm::vec3 axis[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int k = 0; k < std::abs(spheres); ++k)
    for (int octant = 0; octant < 8; ++octant) {
      glm::vec3 corner[3];
      for (int i = 0; i < 3; ++i) corner[i] = light + ((octant >> i) & 1 ? -1.0f : 1.0f) * axis[i];
      const bool counterClockwise = solidAngle(light, corner[0], corner[1], corner[2]) > 0.0;
      if (counterClockwise == (spheres > 0)) std::swap(corner[1], corner[2]);
      for (const glm::vec3& c : corner) cap.split.emplace_back(c, 0.0f);
    }
  return spheres;
}

std::array<glm::vec3, 4> nearRectangle(const glm::mat4& viewProjection) {
  const glm::mat4 inverse = glm::inverse(viewProjection);
  const glm::vec2 ndc[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  std::array<glm::vec3, 4> corners;
  for (int i = 0; i < 4; ++i) {
    const glm::vec4 p = inverse * glm::vec4(ndc[i], -1.0f, 1.0f);
    corners[static_cast<std::size_t>(i)] = glm::vec3(p) / p.w;
  }
  return corners;
}

namespace {

// The plane through a and b that also holds the homogeneous light (a point, or a direction).
Plane planeThrough(const glm::vec3& a, const glm::vec3& b, const glm::vec4& light) {
  const glm::vec3 normal = glm::cross(b - a, glm::vec3(light) - light.w * a);
  return {normal, -glm::dot(normal, a)};
}

float side(const Plane& p, const glm::vec4& point) {
  return glm::dot(glm::vec3(p), glm::vec3(point)) + p.w * point.w;
}

}  // namespace

Frustum occlusionPyramid(const std::array<glm::vec3, 4>& r, const glm::vec4& light) {
  const glm::vec4 centre((r[0] + r[1] + r[2] + r[3]) * 0.25f, 1.0f);  // inside every side plane
  std::vector<Plane> planes;
  for (std::size_t i = 0; i < 4; ++i) {
    Plane p = planeThrough(r[i], r[(i + 1) % 4], light);
    if (side(p, centre) < 0.0f) p = -p;
    planes.push_back(p);
  }
  const glm::vec3 normal = glm::cross(r[1] - r[0], r[3] - r[0]);
  Plane nearPlane(normal, -glm::dot(normal, r[0]));
  if (side(nearPlane, light) < 0.0f) nearPlane = -nearPlane;  // the light's side of the near plane
  planes.push_back(nearPlane);
  // Side planes through an apex bound a cone on both sides of it: close it at the light, with a
  // plane there that has the whole near rectangle on its inside (none when the light is so close
  // to the rectangle that no such plane faces the centre).
  if (light.w != 0.0f) {
    const glm::vec3 apex = glm::vec3(light) / light.w, axis = glm::vec3(centre) - apex;
    const Plane cap(axis, -glm::dot(axis, apex));
    if (std::all_of(r.begin(), r.end(),
                    [&](const glm::vec3& c) { return side(cap, glm::vec4(c, 1.0f)) > 0.0f; }))
      planes.push_back(cap);
  }
  return Frustum{planes};
}

int shadowCase(const Frustum& pyramid, const Frustum& frustum, const glm::vec3& centre, float radius) {
  if (outside(pyramid, BoundingSphere{centre, radius})) return 1;
  if (outside(frustum, BoundingSphere{centre, radius})) return 2;
  return 3;
}

bool culledByLight(const glm::vec3& lightCentre, float lightRadius, const glm::vec3& centre, float radius) {
  return glm::length(centre - lightCentre) > lightRadius + radius;
}

ScissorRect lightScissor(const glm::vec3& centre, float radius, const glm::mat4& viewProjection,
                         glm::ivec2 size) {
  const ScissorRect whole{0, 0, size.x, size.y};
  if (std::isinf(radius)) return whole;
  glm::vec2 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
  int behind = 0;  // corners behind the near plane
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 offset((corner & 1) ? radius : -radius, (corner & 2) ? radius : -radius,
                           (corner & 4) ? radius : -radius);
    const glm::vec4 clip = viewProjection * glm::vec4(centre + offset, 1.0f);
    if (clip.w <= 0.0f || clip.z < -clip.w) {
      ++behind;
      continue;
    }
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    lo = glm::min(lo, ndc);
    hi = glm::max(hi, ndc);
  }
  if (behind == 8) return {};    // all of it behind the camera
  if (behind > 0) return whole;  // the cube reaches the near plane: no finite projection
  if (hi.x < -1.0f || hi.y < -1.0f || lo.x > 1.0f || lo.y > 1.0f) return {};  // off screen
  lo = glm::clamp(lo, -1.0f, 1.0f);
  hi = glm::clamp(hi, -1.0f, 1.0f);
  const glm::vec2 s(size);
  const int x0 = static_cast<int>(std::floor((lo.x + 1.0f) * 0.5f * s.x));
  const int y0 = static_cast<int>(std::floor((lo.y + 1.0f) * 0.5f * s.y));
  const int x1 = static_cast<int>(std::ceil((hi.x + 1.0f) * 0.5f * s.x));
  const int y1 = static_cast<int>(std::ceil((hi.y + 1.0f) * 0.5f * s.y));
  return {x0, y0, x1 - x0, y1 - y0};
}

DepthBounds lightDepthBounds(const glm::vec3& centre, float radius, const glm::mat4& view,
                             const glm::mat4& projection) {
  if (std::isinf(radius)) return {};
  const float distance = -(view * glm::vec4(centre, 1.0f)).z;  // along the view direction
  const auto windowDepth = [&](float d) {
    const glm::vec4 clip = projection * glm::vec4(0.0f, 0.0f, -d, 1.0f);
    return std::clamp(0.5f * clip.z / clip.w + 0.5f, 0.0f, 1.0f);
  };
  const glm::vec4 nearPoint = glm::inverse(projection) * glm::vec4(0.0f, 0.0f, -1.0f, 1.0f);
  const float nearDistance = -nearPoint.z / nearPoint.w;
  const float nearest = distance - radius <= nearDistance ? 0.0f : windowDepth(distance - radius);
  return {nearest, windowDepth(distance + radius)};
}

BoundingSphere worldBounds(const BoundingSphere& local, const glm::mat4& model) {
  const float scale = std::max(
      {glm::length(glm::vec3(model[0])), glm::length(glm::vec3(model[1])), glm::length(glm::vec3(model[2]))});
  return {glm::vec3(model * glm::vec4(local.centre, 1.0f)), local.radius * scale};
}

Recipe recipeFor(ShadowMethod method, int shadowCase, bool anyInPyramid, bool lightCapInCase3,
                 bool directional) {
  const bool fullCaps =
      method == ShadowMethod::EverittKilgard || (method == ShadowMethod::Lengyel && anyInPyramid);
  Recipe r;
  if (shadowCase == 0) return r;  // culled: no volume
  r.zfail = method == ShadowMethod::McGuire ? shadowCase != 1 : fullCaps;
  if (r.zfail && !directional) r.darkCap = fullCaps ? DarkCapKind::BackFaces : DarkCapKind::Fan;
  r.lightCap = r.zfail && (fullCaps || (shadowCase == 3 && lightCapInCase3));
  return r;
}

VolumeIndices volumeOf(const PreparedCaster& caster, const glm::vec4& light, const Recipe& recipe,
                       const std::vector<bool>& lit, const std::vector<SilhouetteEdge>& edges,
                       bool splitFan) {
  const Mesh& mesh = caster.mesh;
  const bool twoSided = !caster.report.closedManifold();  // an open mesh: a volume from each side
  VolumeIndices out;
  CasterVolume& v = out.volume;
  v.zfail = recipe.zfail;
  out.indices = sideIndices(mesh, edges, light.w == 0.0f);
  v.sides = out.indices.size();
  // The light cap is the lit faces as they are; the fan reads them too, to find a light that the
  // fan and the caster enclose together.
  std::vector<std::uint32_t> lightCap, darkCap;
  if (recipe.lightCap || recipe.darkCap == DarkCapKind::Fan) lightCap = lightCapIndices(mesh, lit, twoSided);
  if (recipe.darkCap == DarkCapKind::Fan) {  // one triangle per silhouette edge
    const glm::vec3 point = glm::vec3(light) / light.w;
    DarkCap fan = fanDarkCap(mesh, edges, point, splitFan ? 179.0f : 361.0f);
    v.spheres = std::abs(closeAroundLight(fan, mesh, lightCap, point));  // CPU work, O(f)
    darkCap = fan.indices;
    out.split = fan.split;
    v.splitTriangles = fan.splitTriangles;
    v.splitVertices = out.split.size();
  } else if (recipe.darkCap == DarkCapKind::BackFaces) {
    darkCap = backFaceDarkCapIndices(mesh, lit, twoSided);
  } else if (recipe.darkCap == DarkCapKind::Piece) {
    darkCap = pieceDarkCapIndices(mesh, lit);
  }
  out.indices.insert(out.indices.end(), darkCap.begin(), darkCap.end());
  v.darkCap = darkCap.size();
  if (recipe.lightCap) out.indices.insert(out.indices.end(), lightCap.begin(), lightCap.end());
  v.lightCap = recipe.lightCap ? lightCap.size() : 0;
  for (const SilhouetteEdge& e : edges) out.indices.insert(out.indices.end(), {e.v0, e.v1});
  v.silhouette = 2 * edges.size();
  return out;
}

LightClip lightClip(const glm::vec4& light, float radius, bool bounds, const glm::mat4& view,
                    const glm::mat4& projection, glm::ivec2 size) {
  LightClip clip;
  const bool point = light.w != 0.0f;
  clip.radius = point && bounds ? radius : std::numeric_limits<float>::infinity();
  clip.centre = point ? glm::vec3(light) / light.w : glm::vec3(0.0f);
  clip.scissor = lightScissor(clip.centre, clip.radius, projection * view, size);
  clip.depthBounds = !std::isinf(clip.radius);
  if (clip.depthBounds) clip.depth = lightDepthBounds(clip.centre, clip.radius, view, projection);
  return clip;
}

std::vector<int> shadowCases(const std::vector<BoundingSphere>& casters, const LightClip& clip,
                             const Frustum& pyramid, const Frustum& frustum) {
  std::vector<int> cases;
  for (const BoundingSphere& c : casters) {
    const bool culled =
        !std::isinf(clip.radius) && culledByLight(clip.centre, clip.radius, c.centre, c.radius);
    cases.push_back(culled ? 0 : shadowCase(pyramid, frustum, c.centre, c.radius));
  }
  return cases;
}

bool anyInPyramid(const std::vector<int>& cases) {
  return std::any_of(cases.begin(), cases.end(), [](int c) { return c > 1; });
}

}  // namespace stencil
