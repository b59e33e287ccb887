#include "geometry/shapes.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace stencil {

namespace {

void requirePositive(const char* function, const char* name, float value) {
  // Written as !(value > 0) so NaN is rejected too.
  if (!(value > 0.0f) || !std::isfinite(value)) {
    std::ostringstream message;
    message << function << ": " << name << " must be positive and finite, got " << value;
    throw std::invalid_argument(message.str());
  }
}

void requireAtLeast(const char* function, const char* name, int value, int minimum) {
  if (value < minimum) {
    std::ostringstream message;
    message << function << ": " << name << " must be at least " << minimum << ", got " << value;
    throw std::invalid_argument(message.str());
  }
}

// Indices are 32-bit, and adjacency stores face numbers as int32.
void requireIndexable(const char* function, std::uint64_t vertexCount, std::uint64_t triangleCount) {
  if (vertexCount > std::numeric_limits<std::uint32_t>::max() ||
      triangleCount > static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max())) {
    std::ostringstream message;
    message << function << ": too many segments (" << vertexCount << " vertices, " << triangleCount
            << " triangles)";
    throw std::invalid_argument(message.str());
  }
}

std::uint32_t u32(std::uint64_t value) {
  return static_cast<std::uint32_t>(value);
}

// (cos, sin) of 2*pi*i/n, in double so large n stays accurate.
glm::vec2 circlePoint(int i, int n, double offset = 0.0) {
  const double angle = 2.0 * std::numbers::pi * (static_cast<double>(i) + offset) / static_cast<double>(n);
  return {static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle))};
}

void addVertex(Mesh& mesh, glm::vec3 position, glm::vec3 normal) {
  mesh.positions.push_back(position);
  mesh.normals.push_back(normal);
}

void addTriangle(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  mesh.indices.push_back(a);
  mesh.indices.push_back(b);
  mesh.indices.push_back(c);
}

void reserve(Mesh& mesh, std::uint64_t vertices, std::uint64_t triangles) {
  mesh.positions.reserve(vertices);
  mesh.normals.reserve(vertices);
  mesh.indices.reserve(triangles * 3);
}

}  // namespace

Mesh makePlane(float halfSize, int divisions) {
  requirePositive("makePlane", "halfSize", halfSize);
  requireAtLeast("makePlane", "divisions", divisions, 1);
  const std::uint64_t n = static_cast<std::uint64_t>(divisions);
  const std::uint64_t row = n + 1;
  requireIndexable("makePlane", row * row, 2 * n * n);

  Mesh mesh;
  reserve(mesh, row * row, 2 * n * n);
  const double h = halfSize;
  for (std::uint64_t i = 0; i < row; ++i) {
    const float z = static_cast<float>(-h + 2.0 * h * static_cast<double>(i) / static_cast<double>(n));
    for (std::uint64_t j = 0; j < row; ++j) {
      const float x = static_cast<float>(-h + 2.0 * h * static_cast<double>(j) / static_cast<double>(n));
      addVertex(mesh, {x, 0.0f, z}, {0.0f, 1.0f, 0.0f});
    }
  }
  for (std::uint64_t i = 0; i < n; ++i) {
    for (std::uint64_t j = 0; j < n; ++j) {
      const std::uint32_t p00 = u32(i * row + j);  // +x goes along j, +z along i
      const std::uint32_t p10 = p00 + 1;
      const std::uint32_t p01 = u32(p00 + row);
      const std::uint32_t p11 = p01 + 1;
      // Turning from +z towards +x is counter-clockwise seen from +y.
      addTriangle(mesh, p00, p01, p11);
      addTriangle(mesh, p00, p11, p10);
    }
  }
  return mesh;
}

Mesh makeSquareRing(float outerHalfSize, float innerHalfSize) {
  requirePositive("makeSquareRing", "outerHalfSize", outerHalfSize);
  requirePositive("makeSquareRing", "innerHalfSize", innerHalfSize);
  if (!(innerHalfSize < outerHalfSize))
    throw std::invalid_argument("makeSquareRing: innerHalfSize must be less than outerHalfSize");
  Mesh mesh;
  reserve(mesh, 8, 8);
  // Corners counter-clockwise seen from +y (from +x towards -z), outer ring then inner.
  const glm::vec2 corners[4] = {{1, 1}, {1, -1}, {-1, -1}, {-1, 1}};
  for (const float h : {outerHalfSize, innerHalfSize})
    for (const glm::vec2 c : corners) addVertex(mesh, {h * c.x, 0.0f, h * c.y}, {0.0f, 1.0f, 0.0f});
  for (std::uint32_t i = 0; i < 4; ++i) {  // one trapezoid per side, two triangles each
    const std::uint32_t j = (i + 1) % 4;
    addTriangle(mesh, i, j, 4 + j);
    addTriangle(mesh, i, 4 + j, 4 + i);
  }
  return mesh;
}

Mesh makeScreenQuad() {
  Mesh mesh;
  for (glm::vec2 p : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
    addVertex(mesh, {p, 0.0f}, {0.0f, 0.0f, 1.0f});
  addTriangle(mesh, 0, 1, 2);  // counter-clockwise seen from +z
  addTriangle(mesh, 0, 2, 3);
  return mesh;
}

Mesh makeCube(float halfExtent) {
  requirePositive("makeCube", "halfExtent", halfExtent);
  struct Face {
    glm::vec3 normal, u, v;  // cross(u, v) == normal, so corners in u-then-v order are CCW
  };
  static const Face faces[6] = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},
  };
  Mesh mesh;
  reserve(mesh, 24, 12);
  for (const Face& f : faces) {
    const std::uint32_t base = u32(mesh.positions.size());
    // All components are 0 or +-1 before scaling, so shared corners come out
    // bit-identical across faces and weld exactly.
    addVertex(mesh, (f.normal - f.u - f.v) * halfExtent, f.normal);
    addVertex(mesh, (f.normal + f.u - f.v) * halfExtent, f.normal);
    addVertex(mesh, (f.normal + f.u + f.v) * halfExtent, f.normal);
    addVertex(mesh, (f.normal - f.u + f.v) * halfExtent, f.normal);
    addTriangle(mesh, base, base + 1, base + 2);
    addTriangle(mesh, base, base + 2, base + 3);
  }
  return mesh;
}

Mesh makeSphere(float radius, int slices, int stacks) {
  requirePositive("makeSphere", "radius", radius);
  requireAtLeast("makeSphere", "slices", slices, 3);
  requireAtLeast("makeSphere", "stacks", stacks, 2);
  const std::uint64_t s = static_cast<std::uint64_t>(slices);
  const std::uint64_t rings = static_cast<std::uint64_t>(stacks) - 1;
  requireIndexable("makeSphere", s * rings + 2, 2 * s * rings);

  Mesh mesh;
  reserve(mesh, s * rings + 2, 2 * s * rings);
  addVertex(mesh, {0.0f, radius, 0.0f}, {0.0f, 1.0f, 0.0f});
  for (std::uint64_t i = 1; i <= rings; ++i) {
    const double phi = std::numbers::pi * static_cast<double>(i) / static_cast<double>(stacks);
    const float ringRadius = static_cast<float>(std::sin(phi));
    const float y = static_cast<float>(std::cos(phi));
    for (int j = 0; j < slices; ++j) {
      const glm::vec2 c = circlePoint(j, slices);
      const glm::vec3 direction(ringRadius * c.x, y, ringRadius * c.y);
      addVertex(mesh, direction * radius, glm::normalize(direction));
    }
  }
  const std::uint32_t south = u32(s * rings + 1);
  addVertex(mesh, {0.0f, -radius, 0.0f}, {0.0f, -1.0f, 0.0f});

  // Ring i (1-based), slice j; slices wrap so there is no seam to weld.
  auto ring = [&](std::uint64_t i, std::uint64_t j) { return u32(1 + (i - 1) * s + j % s); };
  for (std::uint64_t j = 0; j < s; ++j) {
    addTriangle(mesh, 0, ring(1, j + 1), ring(1, j));
  }
  for (std::uint64_t i = 1; i < rings; ++i) {
    for (std::uint64_t j = 0; j < s; ++j) {
      // a above b; c, d one slice further round (towards +z from +x).
      const std::uint32_t a = ring(i, j), b = ring(i + 1, j), c = ring(i + 1, j + 1), d = ring(i, j + 1);
      addTriangle(mesh, a, c, b);
      addTriangle(mesh, a, d, c);
    }
  }
  for (std::uint64_t j = 0; j < s; ++j) {
    addTriangle(mesh, ring(rings, j), ring(rings, j + 1), south);
  }
  return mesh;
}

Mesh makeTorus(float majorRadius, float minorRadius, int majorSegments, int minorSegments) {
  requirePositive("makeTorus", "majorRadius", majorRadius);
  requirePositive("makeTorus", "minorRadius", minorRadius);
  if (!(minorRadius < majorRadius)) {
    std::ostringstream message;
    message << "makeTorus: minorRadius (" << minorRadius << ") must be smaller than majorRadius ("
            << majorRadius << ") or the surface intersects itself";
    throw std::invalid_argument(message.str());
  }
  requireAtLeast("makeTorus", "majorSegments", majorSegments, 3);
  requireAtLeast("makeTorus", "minorSegments", minorSegments, 3);
  const std::uint64_t majorCount = static_cast<std::uint64_t>(majorSegments);
  const std::uint64_t minorCount = static_cast<std::uint64_t>(minorSegments);
  requireIndexable("makeTorus", majorCount * minorCount, 2 * majorCount * minorCount);

  Mesh mesh;
  reserve(mesh, majorCount * minorCount, 2 * majorCount * minorCount);
  for (int i = 0; i < majorSegments; ++i) {
    const glm::vec2 around = circlePoint(i, majorSegments);
    const glm::vec3 radial(around.x, 0.0f, around.y);
    for (int j = 0; j < minorSegments; ++j) {
      const glm::vec2 tube = circlePoint(j, minorSegments);
      // Normal of the tube circle: outward from the tube's centre line.
      const glm::vec3 normal = glm::normalize(radial * tube.x + glm::vec3(0.0f, tube.y, 0.0f));
      addVertex(mesh, radial * majorRadius + normal * minorRadius, normal);
    }
  }
  auto at = [&](std::uint64_t i, std::uint64_t j) {
    return u32((i % majorCount) * minorCount + j % minorCount);
  };
  for (std::uint64_t i = 0; i < majorCount; ++i) {
    for (std::uint64_t j = 0; j < minorCount; ++j) {
      // b is one step round the y axis (towards +z), d one step round the tube (towards +y at the outer rim).
      const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      addTriangle(mesh, a, d, c);
      addTriangle(mesh, a, c, b);
    }
  }
  return mesh;
}

Mesh makeCylinder(float radius, float height, int slices) {
  requirePositive("makeCylinder", "radius", radius);
  requirePositive("makeCylinder", "height", height);
  requireAtLeast("makeCylinder", "slices", slices, 3);
  const std::uint64_t s = static_cast<std::uint64_t>(slices);
  requireIndexable("makeCylinder", 4 * s + 2, 4 * s);

  const float top = 0.5f * height;
  const float bottom = -top;
  Mesh mesh;
  reserve(mesh, 4 * s + 2, 4 * s);
  // Rim positions are computed once and reused so side and cap copies weld exactly.
  std::vector<glm::vec3> radial(s);
  for (int j = 0; j < slices; ++j) {
    const glm::vec2 c = circlePoint(j, slices);
    radial[static_cast<std::size_t>(j)] = {c.x, 0.0f, c.y};
  }
  auto rim = [&](std::uint64_t j, float y) {
    return glm::vec3(radial[j] * radius) + glm::vec3(0.0f, y, 0.0f);
  };

  const std::uint32_t sideTop = 0, sideBottom = u32(s);
  for (std::uint64_t j = 0; j < s; ++j) addVertex(mesh, rim(j, top), radial[j]);
  for (std::uint64_t j = 0; j < s; ++j) addVertex(mesh, rim(j, bottom), radial[j]);
  const std::uint32_t topCentre = u32(2 * s), topRing = topCentre + 1;
  addVertex(mesh, {0.0f, top, 0.0f}, {0.0f, 1.0f, 0.0f});
  for (std::uint64_t j = 0; j < s; ++j) addVertex(mesh, rim(j, top), {0.0f, 1.0f, 0.0f});
  const std::uint32_t bottomCentre = u32(3 * s + 1), bottomRing = bottomCentre + 1;
  addVertex(mesh, {0.0f, bottom, 0.0f}, {0.0f, -1.0f, 0.0f});
  for (std::uint64_t j = 0; j < s; ++j) addVertex(mesh, rim(j, bottom), {0.0f, -1.0f, 0.0f});

  for (std::uint64_t j = 0; j < s; ++j) {
    const std::uint32_t j0 = u32(j), j1 = u32((j + 1) % s);
    addTriangle(mesh, sideTop + j0, sideBottom + j1, sideBottom + j0);
    addTriangle(mesh, sideTop + j0, sideTop + j1, sideBottom + j1);
    addTriangle(mesh, topCentre, topRing + j1, topRing + j0);
    addTriangle(mesh, bottomCentre, bottomRing + j0, bottomRing + j1);
  }
  return mesh;
}

Mesh makeCone(float radius, float height, int slices) {
  requirePositive("makeCone", "radius", radius);
  requirePositive("makeCone", "height", height);
  requireAtLeast("makeCone", "slices", slices, 3);
  const std::uint64_t s = static_cast<std::uint64_t>(slices);
  requireIndexable("makeCone", 3 * s + 1, 2 * s);

  const float base = -0.5f * height;
  const glm::vec3 apex(0.0f, 0.5f * height, 0.0f);
  // The side's profile runs from (radius, base) up to (0, apex); rotating its
  // direction (-radius, height) by -90 degrees gives the outward normal
  // (height, radius) in (radial, y).
  auto slantNormal = [&](glm::vec2 c) {
    return glm::normalize(glm::vec3(height * c.x, radius, height * c.y));
  };

  Mesh mesh;
  reserve(mesh, 3 * s + 1, 2 * s);
  std::vector<glm::vec3> rim(s);
  for (int j = 0; j < slices; ++j) {
    const glm::vec2 c = circlePoint(j, slices);
    rim[static_cast<std::size_t>(j)] = {radius * c.x, base, radius * c.y};
    addVertex(mesh, rim[static_cast<std::size_t>(j)], slantNormal(c));
  }
  const std::uint32_t apexes = u32(s);
  for (int j = 0; j < slices; ++j) {
    // The apex has no single normal; each slice's copy takes the smooth
    // cone's normal at the middle of the slice.
    addVertex(mesh, apex, slantNormal(circlePoint(j, slices, 0.5)));
  }
  const std::uint32_t centre = u32(2 * s), ring = centre + 1;
  addVertex(mesh, {0.0f, base, 0.0f}, {0.0f, -1.0f, 0.0f});
  for (std::uint64_t j = 0; j < s; ++j) addVertex(mesh, rim[j], {0.0f, -1.0f, 0.0f});

  for (std::uint64_t j = 0; j < s; ++j) {
    const std::uint32_t j0 = u32(j), j1 = u32((j + 1) % s);
    addTriangle(mesh, j0, apexes + j0, j1);
    addTriangle(mesh, centre, ring + j0, ring + j1);
  }
  return mesh;
}

}  // namespace stencil

namespace stencil {

Mesh makeStairs(int steps, float width, float rise, float run) {
  requireAtLeast("makeStairs", "steps", steps, 1);
  requirePositive("makeStairs", "width", width);
  requirePositive("makeStairs", "rise", rise);
  requirePositive("makeStairs", "run", run);
  requireIndexable("makeStairs", 16ull * static_cast<std::uint64_t>(steps) + 8,
                   12ull * static_cast<std::uint64_t>(steps));
  const int n = steps;
  // Corners on a grid: step i along x, level j up y, side s (+1 front at +z, -1 back). The same
  // expression everywhere, so a corner shared by faces is bit-identical and welds.
  auto corner = [&](int i, int j, int s) {
    return glm::vec3((static_cast<float>(i) - 0.5f * static_cast<float>(n)) * run,
                     (static_cast<float>(j) - 0.5f * static_cast<float>(n)) * rise,
                     0.5f * width * static_cast<float>(s));
  };
  Mesh mesh;
  reserve(mesh, 16ull * n + 8, 12ull * n);
  // One flat face: its own vertices (found by their grid corner, so a side of n steps is built
  // in O(n log n)), its triangles turned to face `normal`.
  struct Face {
    Mesh& mesh;
    glm::vec3 normal;
    std::map<std::array<int, 3>, std::uint32_t> vertices{};
    std::uint32_t vertex(const glm::vec3& p, const glm::ivec3& key) {
      const auto [it, added] = vertices.try_emplace({key.x, key.y, key.z}, u32(mesh.positions.size()));
      if (added) addVertex(mesh, p, normal);
      return it->second;
    }
  };
  auto triangle = [&](Face& face, std::array<glm::ivec3, 3> c) {
    glm::vec3 p[3];
    for (int k = 0; k < 3; ++k) p[k] = corner(c[k].x, c[k].y, c[k].z);
    if (glm::dot(glm::cross(p[1] - p[0], p[2] - p[0]), face.normal) < 0.0f) std::swap(c[1], c[2]);
    for (int k = 0; k < 3; ++k) mesh.indices.push_back(face.vertex(corner(c[k].x, c[k].y, c[k].z), c[k]));
  };
  auto quad = [&](const glm::vec3& normal, glm::ivec2 a, glm::ivec2 b) {  // the edge a-b across the width
    Face face{mesh, normal};
    triangle(face, {glm::ivec3(a, 1), glm::ivec3(b, 1), glm::ivec3(b, -1)});
    triangle(face, {glm::ivec3(a, 1), glm::ivec3(b, -1), glm::ivec3(a, -1)});
  };
  for (int s : {1, -1}) {  // the two sides: column k under step k, fanned from its bottom right corner
    Face side{mesh, glm::vec3(0.0f, 0.0f, static_cast<float>(s))};
    for (int k = 0; k < n; ++k) {
      const glm::ivec3 bottomRight(k + 1, 0, s), topRight(k + 1, k + 1, s), topLeft(k, k + 1, s),
          innerCorner(k, k, s), bottomLeft(k, 0, s);
      triangle(side, {bottomRight, topRight, topLeft});
      triangle(side, {bottomRight, topLeft, innerCorner});
      if (k > 0) triangle(side, {bottomRight, innerCorner, bottomLeft});  // for k = 0 it has no area
    }
  }
  {  // the floor, split at every column so its edges meet the sides' (no T-junctions)
    Face floor{mesh, glm::vec3(0, -1, 0)};
    for (int k = 0; k < n; ++k) {
      triangle(floor, {glm::ivec3(k, 0, 1), glm::ivec3(k + 1, 0, 1), glm::ivec3(k + 1, 0, -1)});
      triangle(floor, {glm::ivec3(k, 0, 1), glm::ivec3(k + 1, 0, -1), glm::ivec3(k, 0, -1)});
    }
  }
  quad({1, 0, 0}, {n, 0}, {n, n});  // the back
  for (int k = 0; k < n; ++k) {
    quad({-1, 0, 0}, {k, k}, {k, k + 1});         // riser
    quad({0, 1, 0}, {k, k + 1}, {k + 1, k + 1});  // tread
  }
  return mesh;
}

}  // namespace stencil
