#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

#include "geometry/adjacency.h"
#include "geometry/cutout.h"
#include "geometry/mesh.h"
#include "geometry/shadow_volume.h"
#include "geometry/shapes.h"
#include "geometry/weld.h"

namespace {

using namespace stencil;

// Two homogeneous points are the same projective point when one is a nonzero multiple of the
// other. GL needs more: a negative multiple puts w < 0 and is clipped, so `oriented` asks for a
// positive one.
::testing::AssertionResult sameProjectivePoint(const glm::vec4& a, const glm::vec4& b, bool oriented = true,
                                               float tolerance = 1e-4f) {
  const float scale = glm::dot(a, b) / glm::dot(b, b);
  if (!(oriented ? scale > 0.0f : scale != 0.0f))
    return ::testing::AssertionFailure() << "opposite or zero: scale " << scale;
  const glm::vec4 d = a - scale * b;
  if (glm::length(d) > tolerance * glm::length(a))
    return ::testing::AssertionFailure() << "(" << a.x << "," << a.y << "," << a.z << "," << a.w << ") vs ("
                                         << b.x << "," << b.y << "," << b.z << "," << b.w << ")";
  return ::testing::AssertionSuccess();
}

Mesh append(Mesh a, const Mesh& b, const glm::mat4& model) {
  const Mesh t = transformed(b, model);
  const auto base = static_cast<std::uint32_t>(a.positions.size());
  a.positions.insert(a.positions.end(), t.positions.begin(), t.positions.end());
  a.normals.insert(a.normals.end(), t.normals.begin(), t.normals.end());
  for (std::uint32_t i : t.indices) a.indices.push_back(base + i);
  return a;
}

double outlineLength(const std::vector<Segment>& outline) {
  double length = 0;
  for (const Segment& s : outline) length += glm::length(s.b - s.a);
  return length;
}

// The signed area, seen from +y, that the fan of flattenedVolume covers (its triangles at w = 1
// that lie in the plane y = h).
double fanArea(const ShadowVolume& volume, float h) {
  double area = 0;
  for (std::size_t i = 0; i < volume.vertices.size(); i += 3) {
    const glm::vec4 a = volume.vertices[i], b = volume.vertices[i + 1], c = volume.vertices[i + 2];
    if (a.w != 1 || b.w != 1 || c.w != 1 || a.y != h || b.y != h || c.y != h) continue;
    // Seen from +y, x to the right and z towards the viewer's bottom: CCW is (b-a) x (c-a) along +y.
    area += 0.5 * glm::cross(glm::vec3(b - a), glm::vec3(c - a)).y;
  }
  return area;
}

TEST(Cutout, LatticeHasItsHolesAndNotchesAsBorderEdges) {
  const std::vector<std::string> rows = latticeRows(1);
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0], ".###.");
  EXPECT_EQ(rows[2], "##.##");
  const Mesh m = makeCutout(rows, 0.5f);
  EXPECT_EQ(m.triangleCount(), 2u * 20u);  // 25 cells less 1 hole and 4 notches
  EXPECT_EQ(weldByPosition(m).mesh.positions.size(), m.positions.size()) << "already welded";
  const EdgeAdjacency adj = buildEdgeAdjacency(m.indices, m.positions.size());
  EXPECT_EQ(adj.report.nonManifoldEdges, 0u);
  EXPECT_EQ(adj.report.inconsistentEdges, 0u);
  // The outline keeps the 5x5 square's 20 unit edges (each notch swaps two for two); the hole has 4.
  EXPECT_EQ(adj.report.borderEdges, 24u);
  for (const glm::vec3& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 1, 0));
  for (const bool lit : facesLight(m, {0, 1, 0, 0})) EXPECT_TRUE(lit) << "every cell faces +y";
}

TEST(Cutout, RejectsBadGrids) {
  EXPECT_THROW(makeCutout({}, 1.0f), std::invalid_argument);
  EXPECT_THROW(makeCutout({"##", "#"}, 1.0f), std::invalid_argument);
  EXPECT_THROW(makeCutout({"..", ".."}, 1.0f), std::invalid_argument);
  EXPECT_THROW(makeCutout({"#"}, 0.0f), std::invalid_argument);
  EXPECT_THROW(latticeRows(0), std::invalid_argument);
}

TEST(ProjectiveFromFivePoints, MapsAllFivePointsUpToScale) {
  const std::array<glm::vec4, 5> from = {glm::vec4(0, 0, 0, 1), glm::vec4(2, 0, 0, 1), glm::vec4(0, 3, 0, 1),
                                         glm::vec4(0, 0, 1, 1), glm::vec4(1, 1, 1, 1)};
  const std::array<glm::vec4, 5> to = {glm::vec4(1, 1, 0, 1), glm::vec4(3, -1, 2, 1), glm::vec4(0, 2, 1, 2),
                                       glm::vec4(1, 0, -1, 0), glm::vec4(-2, 5, 1, 1)};
  const glm::mat4 m = projectiveFromFivePoints(from, to);
  // Five arbitrary points fix the map up to scale, but not the sign each point comes out with.
  for (std::size_t i = 0; i < 5; ++i)
    EXPECT_TRUE(sameProjectivePoint(m * from[i], to[i], false)) << "point " << i;
  const glm::vec4 first = m * from[0];
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(first[k], to[0][k], 1e-5f) << "from[0] lands exactly on to[0]";
}

TEST(ProjectiveFromFivePoints, RecoversAKnownPerspectiveMatrix) {
  const glm::mat4 known =
      glm::perspective(1.0f, 1.3f, 0.5f, 20.0f) * glm::translate(glm::mat4(1), {0.3f, -0.2f, -4.0f});
  std::array<glm::vec4, 5> from = {glm::vec4(1, 0, 0, 1), glm::vec4(0, 1, 0, 1), glm::vec4(0, 0, 1, 1),
                                   glm::vec4(-1, -1, -1, 1), glm::vec4(0.2f, 0.5f, -0.3f, 1)};
  std::array<glm::vec4, 5> to{};
  for (std::size_t i = 0; i < 5; ++i) to[i] = known * from[i];
  const glm::mat4 m = projectiveFromFivePoints(from, to);
  for (const glm::vec4 p : {glm::vec4(3, -2, 5, 1), glm::vec4(0.1f, 0.1f, 0.1f, 1), glm::vec4(1, 2, 3, 0)})
    EXPECT_TRUE(sameProjectivePoint(m * p, known * p, false)) << "a sixth point follows";
}

TEST(ProjectiveFromFivePoints, RefusesFourCoplanarPoints) {
  const std::array<glm::vec4, 5> good = {glm::vec4(0, 0, 0, 1), glm::vec4(1, 0, 0, 1), glm::vec4(0, 1, 0, 1),
                                         glm::vec4(0, 0, 1, 1), glm::vec4(1, 1, 1, 1)};
  std::array<glm::vec4, 5> flat = good;
  flat[3] = glm::vec4(1, 1, 0, 1);  // 0, 1, 2, 3 all in z = 0
  EXPECT_THROW(projectiveFromFivePoints(flat, good), std::invalid_argument);
  EXPECT_THROW(projectiveFromFivePoints(good, flat), std::invalid_argument);
  std::array<glm::vec4, 5> fifthFlat = good;
  fifthFlat[4] = glm::vec4(0.3f, 0.3f, 0, 1);  // the fifth with 0, 1, 2 in z = 0
  EXPECT_THROW(projectiveFromFivePoints(fifthFlat, good), std::invalid_argument);
  std::array<glm::vec4, 5> repeated = good;
  repeated[4] = 2.0f * good[1];  // the same projective point twice
  EXPECT_THROW(projectiveFromFivePoints(good, repeated), std::invalid_argument);
}

TEST(CutoutExtrusionMatrix, IsTheIdentityWithTheLightInItsYColumn) {
  const glm::vec4 light(0.5f, 2.0f, -0.3f, 1.0f);
  const glm::mat4 m = cutoutExtrusionMatrix(light, 50.0f);
  glm::mat4 expected(1.0f);
  expected[1] = light;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(m[c][r], expected[c][r], 1e-5f) << c << "," << r;
  // Scaled lights are the same light.
  const glm::mat4 scaled = cutoutExtrusionMatrix(3.0f * light, 50.0f);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(scaled[c][r], expected[c][r], 1e-5f);
}

TEST(CutoutExtrusionMatrix, TurnsThePrismIntoTheCpuVolume) {
  const Mesh cutout = makeCutout(latticeRows(2), 0.3f);
  const EdgeAdjacency adj = buildEdgeAdjacency(cutout.indices, cutout.positions.size());
  const ShadowVolume prism = cutoutPrism(cutout, adj);
  for (const glm::vec4 light : {glm::vec4(0.4f, 1.5f, 0.2f, 1.0f), glm::vec4(-0.3f, -2.0f, 0.6f, 1.0f)}) {
    const ShadowVolume cpu = silhouetteVolume(cutout, adj, light, kInfinity);
    const glm::mat4 m = cutoutExtrusionMatrix(light, 50.0f);
    // Same edges in the same order; below the plane the CPU walks them the other way round.
    ASSERT_EQ(prism.vertices.size(), cpu.vertices.size());
    std::size_t matched = 0;
    for (const glm::vec4& v : prism.vertices) {
      const glm::vec4 moved = m * v;
      if (v.y == 0.0f) {
        EXPECT_TRUE(sameProjectivePoint(moved, v)) << "near vertices stay";
      } else {
        EXPECT_EQ(v.y, -1.0f);
        EXPECT_NEAR(moved.w, 0.0f, 1e-6f) << "a point light sends the far end to infinity";
        EXPECT_TRUE(sameProjectivePoint(moved, extrudeAway({v.x, 0.0f, v.z}, light, kInfinity)));
      }
      matched += 1;
    }
    EXPECT_EQ(matched, cpu.vertices.size());
  }
}

TEST(CutoutExtrusionMatrix, DirectionalLightReachesAFiniteDistance) {
  const glm::vec4 light = glm::vec4(glm::normalize(glm::vec3(0.3f, 1.0f, 0.1f)), 0.0f);
  const glm::mat4 m = cutoutExtrusionMatrix(light, 40.0f);
  const glm::vec4 far = m * glm::vec4(0.7f, -1.0f, -0.2f, 1.0f);
  EXPECT_TRUE(sameProjectivePoint(far, extrudeAway({0.7f, 0.0f, -0.2f}, light, 40.0f)));
}

TEST(CutoutExtrusionMatrix, RefusesALightInThePlane) {
  // Parallel to the cut-out (a direction with y = 0) or a point light in its plane: edge-on.
  EXPECT_THROW(cutoutExtrusionMatrix({1, 0, 0.5f, 0}, 50.0f), std::invalid_argument);
  EXPECT_THROW(cutoutExtrusionMatrix({2, 0, 1, 1}, 50.0f), std::invalid_argument);
}

TEST(DoubledVertices, BlendedMatricesGiveTheCpuVolume) {
  const Mesh cutout = makeCutout(latticeRows(2), 0.3f);
  const EdgeAdjacency adj = buildEdgeAdjacency(cutout.indices, cutout.positions.size());
  for (const glm::vec4 light : {glm::vec4(0.4f, 1.5f, 0.2f, 1.0f), glm::vec4(-0.3f, -2.0f, 0.6f, 1.0f),
                                glm::vec4(0.2f, 1.0f, 0.1f, 0.0f)}) {
    const std::vector<SilhouetteEdge> edges = possibleSilhouetteEdges(adj, facesLight(cutout, light));
    const std::vector<glm::vec4> doubled = doubledVertexVolume(cutout, edges);
    const ShadowVolume cpu = silhouetteVolume(cutout, adj, light, kInfinity);
    ASSERT_EQ(doubled.size(), cpu.vertices.size());
    const glm::mat4 extrude = extrusionToInfinity(light);
    for (std::size_t i = 0; i < doubled.size(); ++i) {
      // What the vertex shader does: weight w for the model matrix, 1 - w for the extrusion.
      const glm::vec4 p(glm::vec3(doubled[i]), 1.0f);
      const float w = doubled[i].w;
      const glm::vec4 blended = w * p + (1.0f - w) * (extrude * p);
      EXPECT_EQ(blended, cpu.vertices[i]) << "vertex " << i;
    }
  }
}

TEST(ExtrusionToInfinity, PointAndDirectionalLights) {
  EXPECT_EQ(extrusionToInfinity({1, 4, 2, 1}) * glm::vec4(3, 1, 0, 1), glm::vec4(2, -3, -2, 0));
  EXPECT_EQ(extrusionToInfinity({0, 1, 0, 0}) * glm::vec4(3, 1, 0, 1), glm::vec4(0, -1, 0, 0));
}

// Two unit cubes, the second shifted by (1, 0, 1): seen from straight above their shadows are
// two 2x2 squares overlapping in a 1x1 square. The side faces are exactly edge-on to the light.
struct TwoCubes {
  Mesh mesh;
  EdgeAdjacency adj;
  TwoCubes() {
    Mesh cubes = append(Mesh{}, makeCube(1.0f), glm::translate(glm::mat4(1), {0, 3, 0}));
    cubes = append(cubes, makeCube(1.0f), glm::translate(glm::mat4(1), {1, 3.5f, 1}));
    mesh = weldByPosition(cubes).mesh;
    adj = buildEdgeAdjacency(mesh.indices, mesh.positions.size());
  }
};

TEST(FlattenedOutline, EdgeOnFacesCastNothingAndOverlapsLeaveNoInnerEdge) {
  const TwoCubes c;
  ASSERT_TRUE(c.adj.report.closedManifold());
  const glm::vec4 ground(0, 1, 0, 0), fromAbove(0, 1, 0, 0);
  const std::vector<Segment> loops = projectedSilhouette(c.mesh, c.adj, fromAbove, ground);
  // Only the tops face the light; the edge-on sides do not, so the silhouette is the two tops' rims.
  EXPECT_EQ(loops.size(), 8u);
  EXPECT_EQ(windingNumber(loops, ground, {0.5f, 0, 0.5f}), 2) << "covered twice";
  const std::vector<Segment> outline = nonzeroOutline(loops, ground);
  EXPECT_NEAR(outlineLength(outline), 8 + 8 - 4, 1e-4) << "the union's perimeter";
  for (const Segment& s : outline) EXPECT_FLOAT_EQ(s.a.y, 0.0f);
  EXPECT_EQ(windingNumber(outline, ground, {0.5f, 0, 0.5f}), 1) << "the overlap now counts once";
  EXPECT_EQ(windingNumber(outline, ground, {-0.5f, 0, -0.5f}), 1);
  EXPECT_EQ(windingNumber(outline, ground, {1.5f, 0, 1.5f}), 1);
  EXPECT_EQ(windingNumber(outline, ground, {1.5f, 0, -0.5f}), 0) << "outside the union";
  const ShadowVolume volume = flattenedVolume(outline, fromAbove, kInfinity);
  EXPECT_NEAR(fanArea(volume, 0.0f), 7.0, 1e-4) << "the cap's signed area is the union's area";
}

TEST(FlattenedOutline, ATorusFromAboveKeepsItsHole) {
  const Mesh torus =
      weldByPosition(transformed(makeTorus(1.0f, 0.3f, 32, 12), glm::translate(glm::mat4(1), {0, 2, 0})))
          .mesh;
  const EdgeAdjacency adj = buildEdgeAdjacency(torus.indices, torus.positions.size());
  const glm::vec4 ground(0, 1, 0, 0), light(0.1f, 6.0f, 0.05f, 1.0f);
  const std::vector<Segment> outline = nonzeroOutline(projectedSilhouette(torus, adj, light, ground), ground);
  EXPECT_EQ(windingNumber(outline, ground, {0, 0, 0}), 0) << "the hole";
  EXPECT_EQ(windingNumber(outline, ground, {1.2f, 0, 0}), 1) << "the ring";
  EXPECT_EQ(windingNumber(outline, ground, {3.0f, 0, 0}), 0) << "outside";
  const ShadowVolume volume = flattenedVolume(outline, light, kInfinity);
  // The ring's shadow, magnified by 6 / (6 - 2) = 1.5: between radii 1.05 and 1.95, less the polygon's loss.
  const double ring = M_PI * (1.95 * 1.95 - 1.05 * 1.05);
  EXPECT_NEAR(fanArea(volume, 0.0f), ring, 0.05 * ring);
}

TEST(FlattenedOutline, KeepsTheShadowOnTheLeftSeenFromTheLightOnEitherSide) {
  const TwoCubes c;
  for (const float side : {1.0f, -1.0f}) {
    // The same scene mirrored through y = 0: light and cubes below, plane still y = 0.
    const glm::vec4 plane(0, side, 0, 0), light(0.2f, 9.0f * side, 0.1f, 1.0f);
    Mesh mesh = c.mesh;
    if (side < 0) mesh = weldByPosition(transformed(c.mesh, glm::scale(glm::mat4(1), {1, -1, 1}))).mesh;
    const EdgeAdjacency adj = buildEdgeAdjacency(mesh.indices, mesh.positions.size());
    const std::vector<Segment> outline = nonzeroOutline(projectedSilhouette(mesh, adj, light, plane), plane);
    // Seen from the light: the plane's normal as given points towards the light.
    EXPECT_EQ(windingNumber(outline, glm::vec4(0, side, 0, 0), {0.5f, 0, 0.5f}), 1) << "side " << side;
  }
}

TEST(FlattenedOutline, RefusesObjectsNotBetweenTheLightAndThePlane) {
  const TwoCubes c;
  EXPECT_THROW(projectedSilhouette(c.mesh, c.adj, {0, 1, 0, 0}, {0, 1, 0, -3}), std::invalid_argument)
      << "the plane cuts the cubes";
  EXPECT_THROW(projectedSilhouette(c.mesh, c.adj, {0, 4, 0, 1}, {0, 1, 0, 0}), std::invalid_argument)
      << "the light inside the cubes' height";
  EXPECT_THROW(projectedSilhouette(c.mesh, c.adj, {1, 0, 0, 0}, {0, 1, 0, 0}), std::invalid_argument)
      << "a light parallel to the plane";
  const Mesh open = makeCutout({"#"}, 1.0f);
  EXPECT_THROW(projectedSilhouette(open, buildEdgeAdjacency(open.indices, open.positions.size()),
                                   {0, 1, 0, 0}, {0, 1, 0, 1}),
               std::invalid_argument)
      << "not closed";
}

}  // namespace
