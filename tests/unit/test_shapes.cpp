#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>
#include <numbers>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/adjacency.h"
#include "geometry/bounds.h"
#include "geometry/mesh.h"
#include "geometry/shapes.h"
#include "geometry/weld.h"

namespace {

using stencil::Mesh;
constexpr double pi = std::numbers::pi;

// Volume of the polyhedron made by sweeping a polygonal profile (rho, y)
// around the y axis in `slices` straight steps, as the UV shapes do.
// The side quads are planar trapezoids between neighbouring copies of the
// profile, so each horizontal cross-section is a regular slices-gon (or, for
// the torus, one inside another) whose circumradius is the profile's rho at
// that height, with area k * pi * rho^2 where
// k = slices * sin(2 pi / slices) / (2 pi). So the volume is k times the
// volume of revolution of the profile, which is a sum of frustums
// pi * dy * (ra^2 + ra rb + rb^2) / 3. Signed, so a closed profile loop works.
double sweptPolygonVolume(const std::vector<glm::dvec2>& profile, int slices) {
  double revolved = 0.0;
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    const glm::dvec2 a = profile[i], b = profile[i + 1];
    revolved += pi * (a.y - b.y) * (a.x * a.x + a.x * b.x + b.x * b.x) / 3.0;
  }
  const double k = slices * std::sin(2.0 * pi / slices) / (2.0 * pi);
  return std::abs(k * revolved);
}

double sphereExactVolume(double r, int slices, int stacks) {
  std::vector<glm::dvec2> profile;
  for (int i = 0; i <= stacks; ++i) {
    const double phi = pi * i / stacks;
    profile.emplace_back(r * std::sin(phi), r * std::cos(phi));
  }
  return sweptPolygonVolume(profile, slices);
}

double torusExactVolume(double major, double minor, int majorSegments, int minorSegments) {
  std::vector<glm::dvec2> profile;
  for (int j = 0; j <= minorSegments; ++j) {  // closed loop: last point repeats the first
    const double v = 2.0 * pi * j / minorSegments;
    profile.emplace_back(major + minor * std::cos(v), minor * std::sin(v));
  }
  return sweptPolygonVolume(profile, majorSegments);
}

double cylinderExactVolume(double r, double h, int slices) {
  return sweptPolygonVolume({{0, h / 2}, {r, h / 2}, {r, -h / 2}, {0, -h / 2}}, slices);
}

double coneExactVolume(double r, double h, int slices) {
  return sweptPolygonVolume({{0, h / 2}, {r, -h / 2}, {0, -h / 2}}, slices);
}

// A point "behind" p on the inside, so p - inner(p) is the outward direction.
using InnerPoint = std::function<glm::vec3(glm::vec3)>;
const InnerPoint origin = [](glm::vec3) { return glm::vec3(0.0f); };
const InnerPoint belowPlane = [](glm::vec3 p) { return p - glm::vec3(0.0f, 1.0f, 0.0f); };
InnerPoint torusCore(float major) {
  // Nearest point on the tube's centre circle.
  return [major](glm::vec3 p) { return glm::normalize(glm::vec3(p.x, 0.0f, p.z)) * major; };
}
InnerPoint torusFaceCore(float major, int majorSegments) {
  // A face spans one wedge between tube centres c_i and c_i+1. It is planar
  // and symmetric about the wedge's bisector, so its normal is perpendicular
  // to the chord c_i c_i+1; the chord's midpoint is inside and is the
  // reference. (The smooth core circle is not: on a 3-segment torus the
  // chords cut far inside it.)
  return [major, majorSegments](glm::vec3 p) {
    const double wedge = 2.0 * pi / majorSegments;
    double angle = std::atan2(static_cast<double>(p.z), static_cast<double>(p.x));
    if (angle < 0.0) angle += 2.0 * pi;
    const double bisector = (std::floor(angle / wedge) + 0.5) * wedge;
    const double reach = major * std::cos(wedge / 2.0);
    return glm::vec3(glm::dvec3(reach * std::cos(bisector), 0.0, reach * std::sin(bisector)));
  };
}

struct ShapeCase {
  std::string name;
  std::function<Mesh()> make;
  std::size_t vertices, triangles, weldedVertices;
  std::size_t borderEdges;  // after welding
  long euler;               // V - E + F after welding
  InnerPoint inner;
  double exactVolume;         // of the polyhedron itself, not the smooth shape
  InnerPoint faceInner = {};  // for triangle centroids, if inner does not fit
};

std::ostream& operator<<(std::ostream& os, const ShapeCase& c) {
  return os << c.name;
}

// Expected counts follow from how each shape is built (see shapes.h).

ShapeCase planeCase(std::string name, float halfSize, int divisions) {
  // An (n+1) x (n+1) grid of n^2 quads; a disc, so V - E + F = 1.
  const std::size_t n = divisions, row = n + 1;
  return {.name = name,
          .make = [=] { return stencil::makePlane(halfSize, divisions); },
          .vertices = row * row,
          .triangles = 2 * n * n,
          .weldedVertices = row * row,
          .borderEdges = 4 * n,
          .euler = 1,
          .inner = belowPlane,
          .exactVolume = 0.0};
}

ShapeCase cubeCase(std::string name, float h) {
  // 6 faces of 4 vertices and 2 triangles; 8 corners once welded.
  return {.name = name,
          .make = [=] { return stencil::makeCube(h); },
          .vertices = 6 * 4,
          .triangles = 6 * 2,
          .weldedVertices = 8,
          .borderEdges = 0,
          .euler = 2,
          .inner = origin,
          .exactVolume = std::pow(2.0 * h, 3.0)};
}

ShapeCase sphereCase(std::string name, float r, int slices, int stacks) {
  // stacks-1 rings of `slices` plus 2 poles; 2 fans of `slices` triangles
  // and stacks-2 bands of 2*slices.
  const std::size_t s = slices, rings = stacks - 1;
  return {.name = name,
          .make = [=] { return stencil::makeSphere(r, slices, stacks); },
          .vertices = s * rings + 2,
          .triangles = 2 * s + 2 * s * (rings - 1),
          .weldedVertices = s * rings + 2,
          .borderEdges = 0,
          .euler = 2,
          .inner = origin,
          .exactVolume = sphereExactVolume(r, slices, stacks)};
}

ShapeCase torusCase(std::string name, float major, float minor, int majorSegments, int minorSegments) {
  // A grid wrapped both ways: one vertex and two triangles per cell; genus 1, so V - E + F = 0.
  const std::size_t cells = static_cast<std::size_t>(majorSegments) * minorSegments;
  return {.name = name,
          .make = [=] { return stencil::makeTorus(major, minor, majorSegments, minorSegments); },
          .vertices = cells,
          .triangles = 2 * cells,
          .weldedVertices = cells,
          .borderEdges = 0,
          .euler = 0,
          .inner = torusCore(major),
          .exactVolume = torusExactVolume(major, minor, majorSegments, minorSegments),
          .faceInner = torusFaceCore(major, majorSegments)};
}

ShapeCase cylinderCase(std::string name, float r, float h, int slices) {
  // Side: 2 rims of s, 2 triangles per quad. Each cap: a centre and its own
  // rim of s, a fan of s. Welded: 2 rims + 2 centres.
  const std::size_t s = slices;
  return {.name = name,
          .make = [=] { return stencil::makeCylinder(r, h, slices); },
          .vertices = 2 * s + 2 * (s + 1),
          .triangles = 2 * s + 2 * s,
          .weldedVertices = 2 * s + 2,
          .borderEdges = 0,
          .euler = 2,
          .inner = origin,
          .exactVolume = cylinderExactVolume(r, h, slices)};
}

ShapeCase coneCase(std::string name, float r, float h, int slices) {
  // Side: a rim of s and s apex copies, one triangle per slice. Base: a
  // centre, its own rim of s, a fan of s. Welded: rim + apex + centre.
  const std::size_t s = slices;
  return {.name = name,
          .make = [=] { return stencil::makeCone(r, h, slices); },
          .vertices = 2 * s + (s + 1),
          .triangles = s + s,
          .weldedVertices = s + 2,
          .borderEdges = 0,
          .euler = 2,
          .inner = origin,
          .exactVolume = coneExactVolume(r, h, slices)};
}

std::vector<ShapeCase> shapeCases() {
  return {
      planeCase("Plane1", 2.0f, 1),
      planeCase("Plane4", 1.5f, 4),
      cubeCase("Cube", 0.75f),
      sphereCase("SphereMin", 1.0f, 3, 2),
      sphereCase("Sphere", 1.25f, 12, 7),
      torusCase("TorusMin", 1.0f, 0.25f, 3, 3),
      torusCase("Torus", 2.0f, 0.5f, 16, 8),
      cylinderCase("CylinderMin", 1.0f, 1.0f, 3),
      cylinderCase("Cylinder", 0.8f, 2.0f, 10),
      coneCase("ConeMin", 1.0f, 1.0f, 3),
      coneCase("Cone", 1.0f, 1.5f, 9),
  };
}

class ShapeTest : public testing::TestWithParam<ShapeCase> {};

TEST_P(ShapeTest, CountsFollowFromParameters) {
  const ShapeCase& c = GetParam();
  const Mesh m = c.make();
  EXPECT_NO_THROW(stencil::validateMesh(m));
  EXPECT_EQ(m.positions.size(), c.vertices);
  EXPECT_EQ(m.normals.size(), m.positions.size());
  EXPECT_EQ(m.triangleCount(), c.triangles);
  EXPECT_TRUE(stencil::allFinite(m));
}

TEST_P(ShapeTest, WeldedTopology) {
  const ShapeCase& c = GetParam();
  const Mesh m = c.make();
  const Mesh welded = stencil::weldByPosition(m).mesh;
  EXPECT_EQ(welded.positions.size(), c.weldedVertices);
  EXPECT_EQ(welded.triangleCount(), c.triangles);

  const stencil::EdgeAdjacency adj = stencil::buildEdgeAdjacency(welded.indices, welded.positions.size());
  EXPECT_EQ(adj.report.borderEdges, c.borderEdges);
  EXPECT_EQ(adj.report.nonManifoldEdges, 0u);
  EXPECT_EQ(adj.report.inconsistentEdges, 0u);
  EXPECT_EQ(adj.report.degenerateTriangles, 0u);
  EXPECT_EQ(adj.report.closedManifold(), c.borderEdges == 0);
  const long eulerCharacteristic = static_cast<long>(welded.positions.size()) -
                                   static_cast<long>(adj.edges.size()) +
                                   static_cast<long>(welded.triangleCount());
  EXPECT_EQ(eulerCharacteristic, c.euler);
  // On a closed mesh every triangle has three edges, each shared by two: E = 3F/2.
  if (c.borderEdges == 0) {
    EXPECT_EQ(2 * adj.edges.size(), 3 * welded.triangleCount());
  }
}

TEST_P(ShapeTest, NoZeroAreaTriangles) {
  // Stronger than the index check: catches collapsed pole or apex triangles.
  const Mesh m = stencil::weldByPosition(GetParam().make()).mesh;
  for (std::size_t t = 0; t < m.triangleCount(); ++t) {
    const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                    c = m.positions[m.indices[3 * t + 2]];
    EXPECT_GT(glm::length(glm::cross(b - a, c - a)), 1e-6f) << "triangle " << t;
  }
}

TEST_P(ShapeTest, NormalsAreUnitAndOutward) {
  const ShapeCase& c = GetParam();
  const Mesh m = c.make();
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    EXPECT_NEAR(glm::length(m.normals[i]), 1.0f, 1e-5f) << "vertex " << i;
    EXPECT_GT(glm::dot(m.normals[i], m.positions[i] - c.inner(m.positions[i])), 0.0f) << "vertex " << i;
  }
}

TEST_P(ShapeTest, FacesWindCounterClockwiseFromOutside) {
  const ShapeCase& c = GetParam();
  const Mesh m = c.make();
  const InnerPoint& inner = c.faceInner ? c.faceInner : c.inner;
  for (std::size_t t = 0; t < m.triangleCount(); ++t) {
    const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                    d = m.positions[m.indices[3 * t + 2]];
    const glm::vec3 geometric = glm::cross(b - a, d - a);
    const glm::vec3 centroid = (a + b + d) / 3.0f;
    EXPECT_GT(glm::dot(geometric, centroid - inner(centroid)), 0.0f) << "triangle " << t;
    // Shading normals must agree with the winding, or lighting and culling disagree.
    for (int k = 0; k < 3; ++k) {
      EXPECT_GT(glm::dot(geometric, m.normals[m.indices[3 * t + k]]), 0.0f) << "triangle " << t;
    }
  }
}

TEST_P(ShapeTest, VolumeMatchesItsPolyhedron) {
  const ShapeCase& c = GetParam();
  const double volume = stencil::signedVolume(c.make());
  // The plane lies in y = 0, through the origin, so every tetrahedron of the
  // sum is flat and the expected value is exactly 0.
  EXPECT_NEAR(volume, c.exactVolume, c.exactVolume * 1e-5);
  EXPECT_EQ(volume > 0.0, c.borderEdges == 0);
}

INSTANTIATE_TEST_SUITE_P(Shapes, ShapeTest, testing::ValuesIn(shapeCases()),
                         [](const testing::TestParamInfo<ShapeCase>& param) { return param.param.name; });

// Refining the tessellation must approach the analytic volume from below
// (inscribed), with the error shrinking at every step.
void expectConverges(const std::function<Mesh(int)>& make, double analytic) {
  double previousError = analytic;
  for (int n : {8, 16, 32, 64}) {
    const double volume = stencil::signedVolume(make(n));
    const double error = analytic - volume;
    EXPECT_GT(volume, 0.0) << n << " segments";
    EXPECT_GT(error, 0.0) << n << " segments";
    EXPECT_LT(error, previousError) << n << " segments";
    previousError = error;
    if (n == 64) {
      EXPECT_LT(error / analytic, 0.01);
    }
  }
}

TEST(ShapeVolume, SphereConverges) {
  expectConverges([](int n) { return stencil::makeSphere(1.5f, n, n / 2); },
                  4.0 / 3.0 * pi * 1.5 * 1.5 * 1.5);
}

TEST(ShapeVolume, TorusConverges) {
  // Pappus: tube area pi r^2 times path length 2 pi R.
  expectConverges([](int n) { return stencil::makeTorus(2.0f, 0.5f, n, n); },
                  2.0 * pi * pi * 2.0 * 0.5 * 0.5);
}

TEST(ShapeVolume, CylinderConverges) {
  expectConverges([](int n) { return stencil::makeCylinder(0.5f, 3.0f, n); }, pi * 0.5 * 0.5 * 3.0);
}

TEST(ShapeVolume, ConeConverges) {
  expectConverges([](int n) { return stencil::makeCone(1.0f, 2.0f, n); }, pi * 1.0 * 1.0 * 2.0 / 3.0);
}

// Vertices sit on the analytic surfaces.
TEST(ShapeSurface, SphereVerticesOnSphere) {
  const Mesh m = stencil::makeSphere(2.5f, 10, 5);
  for (const glm::vec3& p : m.positions) EXPECT_NEAR(glm::length(p), 2.5f, 1e-5f);
  EXPECT_EQ(m.positions.front(), glm::vec3(0, 2.5f, 0));  // poles on the y axis
  EXPECT_EQ(m.positions.back(), glm::vec3(0, -2.5f, 0));
}

TEST(ShapeSurface, TorusVerticesOnTorus) {
  // (sqrt(x^2 + z^2) - R)^2 + y^2 = r^2
  const Mesh m = stencil::makeTorus(3.0f, 1.0f, 12, 6);
  for (const glm::vec3& p : m.positions) {
    const float rho = glm::length(glm::vec2(p.x, p.z));
    EXPECT_NEAR(std::hypot(rho - 3.0f, p.y), 1.0f, 1e-5f);
  }
}

TEST(ShapeSurface, CylinderVerticesOnRimsOrAxis) {
  const Mesh m = stencil::makeCylinder(0.5f, 4.0f, 7);
  for (const glm::vec3& p : m.positions) {
    EXPECT_EQ(std::abs(p.y), 2.0f);
    const float rho = glm::length(glm::vec2(p.x, p.z));
    EXPECT_TRUE(rho < 1e-6f || std::abs(rho - 0.5f) < 1e-6f) << rho;
  }
}

TEST(ShapeSurface, ConeBaseAndApex) {
  const Mesh m = stencil::makeCone(0.5f, 4.0f, 7);
  for (const glm::vec3& p : m.positions) {
    const float rho = glm::length(glm::vec2(p.x, p.z));
    if (p.y == 2.0f) {
      EXPECT_LT(rho, 1e-6f);  // apex
    } else {
      EXPECT_EQ(p.y, -2.0f);
      EXPECT_TRUE(rho < 1e-6f || std::abs(rho - 0.5f) < 1e-6f) << rho;
    }
  }
}

TEST(ShapeSurface, SquareRingIsTheSquareMinusTheHole) {
  const Mesh m = stencil::makeSquareRing(2.0f, 0.5f);
  ASSERT_EQ(m.positions.size(), 8u);
  ASSERT_EQ(m.triangleCount(), 8u);
  // Every triangle faces +y and the areas add up to 4^2 - 1^2.
  double area = 0.0;
  for (std::size_t t = 0; t < m.triangleCount(); ++t) {
    const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                    c = m.positions[m.indices[3 * t + 2]];
    const glm::vec3 n = glm::cross(b - a, c - a);
    EXPECT_GT(n.y, 0.0f) << "triangle " << t << " faces down";
    area += 0.5 * n.y;
  }
  EXPECT_NEAR(area, 16.0 - 1.0, 1e-5);
  for (const glm::vec3& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 1, 0));
  // An annulus: two border loops of four edges, nothing else open.
  const auto adjacency = stencil::buildEdgeAdjacency(m.indices, m.positions.size());
  EXPECT_EQ(adjacency.report.borderEdges, 8u);
  EXPECT_EQ(adjacency.report.nonManifoldEdges, 0u);
  EXPECT_THROW(stencil::makeSquareRing(1.0f, 1.0f), std::invalid_argument);
  EXPECT_THROW(stencil::makeSquareRing(1.0f, 0.0f), std::invalid_argument);
}

TEST(ShapeSurface, PlaneSpansItsHalfSize) {
  const Mesh m = stencil::makePlane(1.5f, 3);
  for (const glm::vec3& p : m.positions) {
    EXPECT_EQ(p.y, 0.0f);
    EXPECT_LE(std::abs(p.x), 1.5f);
    EXPECT_LE(std::abs(p.z), 1.5f);
  }
  for (const glm::vec3& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 1, 0));
  // The grid corners are exactly +-halfSize.
  EXPECT_EQ(m.positions.front(), glm::vec3(-1.5f, 0, -1.5f));
  EXPECT_EQ(m.positions.back(), glm::vec3(1.5f, 0, 1.5f));
}

// Normals match the analytic surface, not just "roughly outward".
void expectVecNear(glm::vec3 actual, glm::vec3 expected, float tolerance, std::size_t vertex) {
  EXPECT_LT(glm::distance(actual, expected), tolerance)
      << "vertex " << vertex << ": (" << actual.x << ", " << actual.y << ", " << actual.z << ") vs ("
      << expected.x << ", " << expected.y << ", " << expected.z << ")";
}

TEST(ShapeNormals, SphereNormalIsPositionOverRadius) {
  const Mesh m = stencil::makeSphere(2.0f, 11, 6);
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    expectVecNear(m.normals[i], m.positions[i] / 2.0f, 1e-6f, i);
}

TEST(ShapeNormals, TorusNormalPointsAwayFromTubeCentre) {
  const Mesh m = stencil::makeTorus(2.0f, 0.5f, 9, 7);
  const InnerPoint core = torusCore(2.0f);
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    expectVecNear(m.normals[i], (m.positions[i] - core(m.positions[i])) / 0.5f, 1e-5f, i);
  }
}

TEST(ShapeNormals, FlatFacesUseTheirPlaneNormal) {
  // Cube faces, the caps and the plane: a triangle whose three vertices share
  // one normal is flat-shaded, and that normal must be its plane's.
  std::size_t flat = 0;
  for (const Mesh& m : {stencil::makePlane(1.0f, 2), stencil::makeCube(1.0f),
                        stencil::makeCylinder(1.0f, 2.0f, 6), stencil::makeCone(1.0f, 2.0f, 6)}) {
    for (std::size_t t = 0; t < m.triangleCount(); ++t) {
      const std::uint32_t* tri = &m.indices[3 * t];
      if (m.normals[tri[0]] != m.normals[tri[1]] || m.normals[tri[0]] != m.normals[tri[2]]) continue;
      ++flat;
      const glm::vec3 a = m.positions[tri[0]], b = m.positions[tri[1]], c = m.positions[tri[2]];
      const glm::vec3 geometric = glm::normalize(glm::cross(b - a, c - a));
      expectVecNear(m.normals[tri[0]], geometric, 1e-6f, tri[0]);
    }
  }
  // 2*2*2 plane + 12 cube + 2*6 cylinder caps + 6 cone base triangles.
  EXPECT_EQ(flat, 8u + 12u + 12u + 6u);
}

TEST(ShapeNormals, CylinderSideIsRadialCapsAreVertical) {
  const int slices = 7;
  const Mesh m = stencil::makeCylinder(0.5f, 3.0f, slices);
  std::size_t radial = 0, capped = 0;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const glm::vec3 p = m.positions[i], n = m.normals[i];
    if (n == glm::vec3(0.0f, p.y > 0.0f ? 1.0f : -1.0f, 0.0f)) {
      ++capped;
    } else {
      ++radial;
      expectVecNear(n, glm::normalize(glm::vec3(p.x, 0.0f, p.z)), 1e-6f, i);
    }
  }
  EXPECT_EQ(radial, 2u * slices);      // one per rim vertex, top and bottom
  EXPECT_EQ(capped, 2u * slices + 2);  // both rims again, plus the two centres
}

TEST(ShapeNormals, ConeSideFollowsTheSlant) {
  // The side's profile (r, -h/2) -> (0, h/2) has outward normal (h, r) in
  // (radial, y) at every angle. Base rim copies carry it at their own angle.
  // Apex copies belong to one side triangle each and carry it at the middle
  // angle of that triangle's base edge.
  const float r = 1.0f, h = 2.0f;
  const int slices = 8;
  const Mesh m = stencil::makeCone(r, h, slices);
  auto slant = [&](glm::vec3 towards) {
    const glm::vec3 out = glm::normalize(glm::vec3(towards.x, 0.0f, towards.z));
    return glm::normalize(glm::vec3(h * out.x, r, h * out.z));
  };
  std::vector<int> uses(m.positions.size(), 0);
  for (std::uint32_t index : m.indices) ++uses[index];
  std::size_t apexes = 0, slanted = 0, base = 0;
  for (std::size_t t = 0; t < m.triangleCount(); ++t) {
    const std::uint32_t* tri = &m.indices[3 * t];
    for (int k = 0; k < 3; ++k) {
      if (m.positions[tri[k]].y != h / 2.0f) continue;
      ++apexes;
      EXPECT_EQ(uses[tri[k]], 1);
      const glm::vec3 baseMid = m.positions[tri[(k + 1) % 3]] + m.positions[tri[(k + 2) % 3]];
      expectVecNear(m.normals[tri[k]], slant(baseMid), 1e-6f, tri[k]);
    }
  }
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const glm::vec3 p = m.positions[i], n = m.normals[i];
    if (p.y == h / 2.0f) continue;
    if (n == glm::vec3(0.0f, -1.0f, 0.0f)) {
      ++base;
    } else {
      ++slanted;
      expectVecNear(n, slant(p), 1e-6f, i);
    }
  }
  EXPECT_EQ(apexes, static_cast<std::size_t>(slices));
  EXPECT_EQ(slanted, static_cast<std::size_t>(slices));
  EXPECT_EQ(base, static_cast<std::size_t>(slices) + 1);
}

TEST(ShapeParameters, RejectBadSizes) {
  const float nan = std::nanf("");
  const float inf = std::numeric_limits<float>::infinity();
  for (const float bad : {0.0f, -1.0f, nan, inf}) {
    EXPECT_THROW(stencil::makePlane(bad), std::invalid_argument);
    EXPECT_THROW(stencil::makeCube(bad), std::invalid_argument);
    EXPECT_THROW(stencil::makeSphere(bad, 8, 4), std::invalid_argument);
    EXPECT_THROW(stencil::makeTorus(bad, 0.5f, 8, 8), std::invalid_argument);
    EXPECT_THROW(stencil::makeTorus(2.0f, bad, 8, 8), std::invalid_argument);
    EXPECT_THROW(stencil::makeCylinder(bad, 1.0f, 8), std::invalid_argument);
    EXPECT_THROW(stencil::makeCylinder(1.0f, bad, 8), std::invalid_argument);
    EXPECT_THROW(stencil::makeCone(bad, 1.0f, 8), std::invalid_argument);
    EXPECT_THROW(stencil::makeCone(1.0f, bad, 8), std::invalid_argument);
  }
  // A tube as thick as the ring is wide would pass through the axis.
  EXPECT_THROW(stencil::makeTorus(1.0f, 1.0f, 8, 8), std::invalid_argument);
  EXPECT_THROW(stencil::makeTorus(1.0f, 2.0f, 8, 8), std::invalid_argument);
}

TEST(ShapeParameters, RejectTooFewSegments) {
  EXPECT_THROW(stencil::makePlane(1.0f, 0), std::invalid_argument);
  EXPECT_THROW(stencil::makeSphere(1.0f, 2, 4), std::invalid_argument);
  EXPECT_THROW(stencil::makeSphere(1.0f, 8, 1), std::invalid_argument);
  EXPECT_THROW(stencil::makeTorus(2.0f, 0.5f, 2, 8), std::invalid_argument);
  EXPECT_THROW(stencil::makeTorus(2.0f, 0.5f, 8, 2), std::invalid_argument);
  EXPECT_THROW(stencil::makeCylinder(1.0f, 1.0f, 2), std::invalid_argument);
  EXPECT_THROW(stencil::makeCone(1.0f, 1.0f, -3), std::invalid_argument);
}

TEST(ShapeParameters, MessageNamesTheParameter) {
  try {
    stencil::makeSphere(1.0f, 8, 1);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("makeSphere"), std::string::npos) << what;
    EXPECT_NE(what.find("stacks"), std::string::npos) << what;
  }
}

}  // namespace

TEST(ScreenQuad, CoversClipSpaceFacingPlusZ) {
  using namespace stencil;
  const Mesh quad = makeScreenQuad();
  ASSERT_EQ(quad.positions.size(), 4u);
  ASSERT_EQ(quad.triangleCount(), 2u);
  const Aabb box = boundsOf(quad.positions);
  EXPECT_EQ(box.min, glm::vec3(-1, -1, 0));
  EXPECT_EQ(box.max, glm::vec3(1, 1, 0));
  for (glm::vec3 n : quad.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
  // Counter-clockwise seen from +z, and the two triangles tile the square: areas add to 4.
  float area = 0;
  for (std::size_t t = 0; t < 2; ++t) {
    const glm::vec3 a = quad.positions[quad.indices[3 * t]], b = quad.positions[quad.indices[3 * t + 1]],
                    c = quad.positions[quad.indices[3 * t + 2]];
    const float z = glm::cross(b - a, c - a).z;
    EXPECT_GT(z, 0.0f);
    area += z / 2;
  }
  EXPECT_FLOAT_EQ(area, 4.0f);
}

// Stairs: a closed solid whose volume is the sum of its columns, step k (from 1) k rises high.
TEST(Stairs, ClosedSolidOfTheRightVolumeWithFlatOutwardFaces) {
  using namespace stencil;
  for (const int steps : {1, 2, 7}) {
    const float width = 1.5f, rise = 0.25f, run = 0.5f;
    const Mesh m = makeStairs(steps, width, rise, run);
    const auto n = static_cast<std::size_t>(steps);
    EXPECT_EQ(m.positions.size(), 16 * n + 8);
    EXPECT_EQ(m.triangleCount(), 12 * n);
    const Mesh welded = weldByPosition(m).mesh;
    EXPECT_EQ(welded.positions.size(), 6 * n + 2);
    const EdgeAdjacency adj = buildEdgeAdjacency(welded.indices, welded.positions.size());
    EXPECT_TRUE(adj.report.closedManifold()) << steps << " steps";
    EXPECT_EQ(static_cast<long>(welded.positions.size()) - static_cast<long>(adj.edges.size()) +
                  static_cast<long>(welded.triangleCount()),
              2);
    EXPECT_NEAR(signedVolume(m), double(width) * rise * run * steps * (steps + 1) / 2.0, 1e-5);
    const Aabb box = boundsOf(m.positions);
    EXPECT_FLOAT_EQ(box.min.x, -0.5f * run * static_cast<float>(steps));
    EXPECT_FLOAT_EQ(box.max.y, 0.5f * rise * static_cast<float>(steps));
    EXPECT_FLOAT_EQ(box.max.z, 0.5f * width);
    for (std::size_t t = 0; t < m.triangleCount(); ++t) {
      const std::uint32_t* i = &m.indices[3 * t];
      const glm::vec3 face =
          glm::cross(m.positions[i[1]] - m.positions[i[0]], m.positions[i[2]] - m.positions[i[0]]);
      ASSERT_GT(glm::length(face), 0.0f) << "triangle " << t;
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(glm::dot(glm::normalize(face), m.normals[i[k]]), 1.0f, 1e-6f);
    }
  }
  EXPECT_THROW(makeStairs(0, 1, 1, 1), std::invalid_argument);
  EXPECT_THROW(makeStairs(3, 1, -1, 1), std::invalid_argument);
}
