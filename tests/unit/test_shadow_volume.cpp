#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <glm/geometric.hpp>
#include <map>
#include <stdexcept>
#include <utility>

#include "geometry/adjacency.h"
#include "geometry/shadow_volume.h"
#include "geometry/shapes.h"
#include "geometry/solid.h"
#include "geometry/weld.h"

namespace {

using namespace stencil;

Mesh weldedCube() {
  return weldByPosition(makeCube(1.0f)).mesh;
}  // [-1,1]^3, 8 vertices

// A volume's sides closed by its caps: the lit triangles (near, facing out towards the light)
// and the same triangles pushed away and turned round (far). Only for finite distances.
Mesh cappedWithLitFaces(const Mesh& caster, const std::vector<bool>& lit, const ShadowVolume& sides,
                        const glm::vec4& light, float distance) {
  Mesh m;
  auto add = [&m](const glm::vec3& p) {
    m.positions.push_back(p);
    m.indices.push_back(static_cast<std::uint32_t>(m.positions.size() - 1));
  };
  for (const glm::vec4& v : sides.vertices) add(glm::vec3(v) / v.w);
  for (std::size_t t = 0; t < lit.size(); ++t) {
    if (!lit[t]) continue;
    glm::vec3 p[3];
    for (int k = 0; k < 3; ++k) p[k] = caster.positions[caster.indices[3 * t + k]];
    for (int k = 0; k < 3; ++k) add(p[k]);
    for (int k = 2; k >= 0; --k) add(glm::vec3(extrudeAway(p[k], light, distance)));
  }
  return m;
}

TEST(ExtrudeAway, PointLightFiniteAndInfinite) {
  const glm::vec4 light(0, 5, 0, 1);
  const glm::vec4 near = extrudeAway({3, 1, 0}, light, 10.0f);  // away along (3,-4,0)/5
  EXPECT_FLOAT_EQ(near.w, 1.0f);
  EXPECT_NEAR(near.x, 3.0f + 6.0f, 1e-5f);
  EXPECT_NEAR(near.y, 1.0f - 8.0f, 1e-5f);
  const glm::vec4 far = extrudeAway({3, 1, 0}, light, kInfinity);
  EXPECT_EQ(far, glm::vec4(3, -4, 0, 0));  // the direction p - L at w = 0
}

TEST(ExtrudeAway, DirectionalLightMovesEveryPointTheSameWay) {
  const glm::vec4 light(0, 2, 0, 0);  // light from above
  EXPECT_EQ(extrudeAway({1, 1, 1}, light, 3.0f), glm::vec4(1, -2, 1, 1));
  EXPECT_EQ(extrudeAway({7, 0, -2}, light, kInfinity), glm::vec4(0, -2, 0, 0));
}

TEST(ExtrudeAway, ALightOnThePointLeavesItWhereItIs) {
  EXPECT_EQ(extrudeAway({1, 2, 3}, {1, 2, 3, 1}, 5.0f), glm::vec4(1, 2, 3, 1));
}

TEST(FacesLight, CubeSeesOneFaceFromAPointOnItsAxis) {
  const Mesh cube = makeCube(1.0f);
  const std::vector<bool> lit = facesLight(cube, {5, 0, 0, 1});
  int count = 0;
  for (std::size_t t = 0; t < lit.size(); ++t) {
    if (!lit[t]) continue;
    ++count;
    for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(cube.positions[cube.indices[3 * t + k]].x, 1.0f);
  }
  EXPECT_EQ(count, 2);  // the +x face; from (5,0,0) every side face's plane has the light behind it
}

TEST(FacesLight, EdgeOnFacesDoNotFaceTheLight) {
  // A directional light along +x grazes the four faces parallel to x.
  const std::vector<bool> lit = facesLight(makeCube(1.0f), {1, 0, 0, 0});
  int count = 0;
  for (bool l : lit) count += l;
  EXPECT_EQ(count, 2);
}

TEST(SilhouetteEdges, CubeFromAnAxisIsTheLitFaceOutlineWalkedByIt) {
  const Mesh cube = weldedCube();
  const EdgeAdjacency adjacency = buildEdgeAdjacency(cube.indices, cube.positions.size());
  const std::vector<bool> lit = facesLight(cube, {0, 0, 1, 0});  // the +z face
  const std::vector<SilhouetteEdge> edges = possibleSilhouetteEdges(adjacency, lit);
  ASSERT_EQ(edges.size(), 4u);
  for (const SilhouetteEdge& e : edges) {
    const glm::vec3 a = cube.positions[e.v0], b = cube.positions[e.v1];
    EXPECT_FLOAT_EQ(a.z, 1.0f);
    EXPECT_FLOAT_EQ(b.z, 1.0f);
    // Walked counter-clockwise seen from +z: the face's centre (0,0,1) lies to the left.
    EXPECT_GT(glm::cross(b - a, glm::vec3(0, 0, 1) - a).z, 0.0f);
  }
}

TEST(SilhouetteEdges, BorderEdgesOfAnOpenCutOutFromEitherSide) {
  const Mesh square = makePlane(1.0f);  // y = 0, facing +y, four border edges
  const EdgeAdjacency adjacency = buildEdgeAdjacency(square.indices, square.positions.size());
  for (float side : {1.0f, -1.0f}) {
    const std::vector<bool> lit = facesLight(square, {0, side, 0, 0});
    const std::vector<SilhouetteEdge> edges = possibleSilhouetteEdges(adjacency, lit);
    ASSERT_EQ(edges.size(), 4u);
    for (const SilhouetteEdge& e : edges) {  // counter-clockwise seen from the light's side
      const glm::vec3 a = square.positions[e.v0], b = square.positions[e.v1];
      EXPECT_GT(side * glm::cross(b - a, -a).y, 0.0f);
    }
  }
}

TEST(SilhouetteVolume, DirectionalPrismHasTheDerivedVolumeAndFacesOut) {
  // Light from +z: the volume behind the +z face is a 2 x 2 x d prism (volume 4d) once closed.
  const Mesh cube = weldedCube();
  const EdgeAdjacency adjacency = buildEdgeAdjacency(cube.indices, cube.positions.size());
  const glm::vec4 light(0, 0, 1, 0);
  const float d = 3.0f;
  const ShadowVolume sides = silhouetteVolume(cube, adjacency, light, d);
  EXPECT_EQ(sides.triangleCount(), 8u);  // 4 edges, 2 triangles each
  const Mesh closed = cappedWithLitFaces(cube, facesLight(cube, light), sides, light, d);
  EXPECT_NEAR(signedVolume(closed), 4.0 * d, 1e-4);
  const Mesh welded = weldByPosition(closed).mesh;
  EXPECT_TRUE(buildEdgeAdjacency(welded.indices, welded.positions.size()).report.closedManifold());
}

TEST(SilhouetteVolume, PointLightPushesAlongTheRaysAndFacesOut) {
  // Light at (0,0,3) over the +z face: every vertex is a corner of that face or such a corner
  // pushed 2 further along the ray from the light, and every triangle faces away from the axis.
  const Mesh cube = weldedCube();
  const EdgeAdjacency adjacency = buildEdgeAdjacency(cube.indices, cube.positions.size());
  const glm::vec3 light(0, 0, 3);
  const ShadowVolume sides = silhouetteVolume(cube, adjacency, glm::vec4(light, 1), 2.0f);
  ASSERT_EQ(sides.triangleCount(), 8u);
  for (const glm::vec4& v : sides.vertices) {
    const glm::vec3 p(v);
    if (p.z == 1.0f) {
      EXPECT_FLOAT_EQ(std::abs(p.x), 1.0f);
      EXPECT_FLOAT_EQ(std::abs(p.y), 1.0f);
      continue;
    }
    const glm::vec3 corner(p.x > 0 ? 1 : -1, p.y > 0 ? 1 : -1, 1);
    EXPECT_NEAR(glm::length(p - light) - glm::length(corner - light), 2.0f, 1e-5f);
    EXPECT_NEAR(glm::length(glm::cross(glm::normalize(p - corner), glm::normalize(corner - light))), 0.0f,
                1e-5f);
  }
  for (std::size_t t = 0; t < sides.triangleCount(); ++t) {
    const glm::vec3 a(sides.vertices[3 * t]), b(sides.vertices[3 * t + 1]), c(sides.vertices[3 * t + 2]);
    const glm::vec3 centre = (a + b + c) / 3.0f;
    EXPECT_GT(glm::dot(glm::cross(b - a, c - a), glm::vec3(centre.x, centre.y, 0)), 0.0f) << "triangle " << t;
  }
}

TEST(AddExtrudedEdge, AnEdgeWalkedBothWaysGivesTheSameTrianglesFacingOpposite) {
  // Two triangles sharing an edge extrude it both ways; the quads must cover the same pixels, so
  // they are split on the same diagonal: the same vertex sets, wound the other way round.
  const glm::vec3 a(0.3f, -1.0f, 0.5f), b(-0.2f, 1.0f, 0.5f);
  const glm::vec4 light(0.1f, 0.2f, 4.0f, 1.0f);
  ShadowVolume forward, backward;
  addExtrudedEdge(forward, a, b, light, kInfinity);
  addExtrudedEdge(backward, b, a, light, kInfinity);
  ASSERT_EQ(forward.triangleCount(), 2u);
  ASSERT_EQ(backward.triangleCount(), 2u);
  for (std::size_t t = 0; t < 2; ++t) {
    const glm::vec4* f = &forward.vertices[3 * t];
    bool matched = false;
    for (std::size_t u = 0; u < 2; ++u) {
      const glm::vec4* g = &backward.vertices[3 * u];
      for (int r = 0; r < 3; ++r)  // g reversed and rotated equals f
        matched |= f[0] == g[(r + 2) % 3] && f[1] == g[(r + 1) % 3] && f[2] == g[r];
    }
    EXPECT_TRUE(matched) << "triangle " << t;
  }
}

TEST(SilhouetteVolume, InfiniteExtrusionPutsHalfTheVerticesAtInfinity) {
  const Mesh cube = weldedCube();
  const EdgeAdjacency adjacency = buildEdgeAdjacency(cube.indices, cube.positions.size());
  const ShadowVolume sides = silhouetteVolume(cube, adjacency, {2, 3, 4, 1}, kInfinity);
  std::size_t atInfinity = 0;
  for (const glm::vec4& v : sides.vertices) atInfinity += v.w == 0.0f;
  EXPECT_EQ(atInfinity, sides.vertices.size() / 2);
  EXPECT_GT(sides.triangleCount(), 0u);
}

TEST(SilhouetteVolume, RefusesANonManifoldMesh) {
  Mesh fin;  // three triangles on one edge
  fin.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  fin.indices = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  const EdgeAdjacency adjacency = buildEdgeAdjacency(fin.indices, fin.positions.size());
  EXPECT_THROW(silhouetteVolume(fin, adjacency, {0, 0, 5, 1}, 1.0f), std::invalid_argument);
}

TEST(PolygonVolumes, UnionOfPerTriangleVolumesHasTheSilhouettesVolume) {
  // Each lit triangle's prism closed by its own caps: 2 prisms of 2d each, 4d together, the
  // same as the silhouette's prism; the shared diagonal's two quads cancel.
  const Mesh cube = weldedCube();
  const glm::vec4 light(0, 0, 1, 0);
  const float d = 3.0f;
  const ShadowVolume volumes = polygonVolumes(cube, light, d);
  EXPECT_EQ(volumes.triangleCount(), 12u);  // 2 triangles x 3 quads x 2
  EXPECT_NEAR(signedVolume(cappedWithLitFaces(cube, facesLight(cube, light), volumes, light, d)), 4.0 * d,
              1e-4);
}

TEST(PolygonVolumes, TwoSidedCutOutCastsFromBehind) {
  const Mesh square = makePlane(1.0f);
  const glm::vec4 below(0, -1, 0, 0);
  EXPECT_EQ(polygonVolumes(square, below, 1.0f).triangleCount(), 0u);
  const ShadowVolume twoSided = polygonVolumes(square, below, 1.0f, true);
  ASSERT_EQ(twoSided.triangleCount(), 12u);
  // Extruded upwards (away from a light below), every quad still faces out of its prism:
  // the prisms of the square's triangles close to 2 * (area 2 each) * 1.
  Mesh flipped = square;
  for (std::size_t t = 0; t < flipped.triangleCount(); ++t)
    std::swap(flipped.indices[3 * t + 1], flipped.indices[3 * t + 2]);
  EXPECT_NEAR(signedVolume(cappedWithLitFaces(flipped, facesLight(flipped, below), twoSided, below, 1.0f)),
              4.0, 1e-4);
}

}  // namespace

namespace {

using stencil::PreparedCaster;

TEST(PreparedCaster, WeldsTheCreasesAndGivesTheSameVolume) {
  const PreparedCaster caster = prepareCaster(stencil::makeCube(1.0f));  // 24 vertices split at the creases
  EXPECT_EQ(caster.mesh.positions.size(), 8u);
  EXPECT_TRUE(caster.adjacency.report.closedManifold());
  const glm::vec4 light(2, 3, 4, 1);
  EXPECT_EQ(stencil::silhouetteVolume(caster, light, 2.0f).vertices,
            stencil::silhouetteVolume(caster.mesh, caster.adjacency, light, 2.0f).vertices);
}

}  // namespace

namespace {

// Every directed edge of the triangles walked once the other way too: a closed surface, points
// at infinity included (a w = 0 vertex is its direction). Returns the edges left unmatched.
std::size_t unmatchedEdges(const ShadowVolume& v) {
  std::map<std::pair<std::array<float, 4>, std::array<float, 4>>, int> walked;
  const auto key = [](const glm::vec4& p) { return std::array<float, 4>{p.x, p.y, p.z, p.w}; };
  for (std::size_t t = 0; t < v.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) {
      const auto a = key(v.vertices[3 * t + k]), b = key(v.vertices[3 * t + (k + 1) % 3]);
      if (a == b) continue;  // a degenerate triangle's collapsed edge
      ++walked[{a, b}];
      --walked[{b, a}];
    }
  std::size_t unmatched = 0;
  for (const auto& [edge, n] : walked) unmatched += n > 0 ? static_cast<std::size_t>(n) : 0;
  return unmatched;
}

Mesh asMesh(const ShadowVolume& v) {  // finite volumes only
  Mesh m;
  for (const glm::vec4& p : v.vertices) {
    m.positions.push_back(glm::vec3(p) / p.w);
    m.indices.push_back(static_cast<std::uint32_t>(m.indices.size()));
  }
  return m;
}

}  // namespace

TEST(ClosedVolume, DirectionalPrismIsTheCubeSweptDown) {
  // Light straight above the cube [-1,1]^3: the top is the light cap; the four sides (edge-on,
  // so unlit) and the bottom, pushed d down, the dark cap; the top's outline extruded, the sides.
  // The closed volume is the box from y = -1 - d to y = 1: 4 (2 + d).
  const Mesh cube = weldedCube();
  const EdgeAdjacency adjacency = buildEdgeAdjacency(cube.indices, cube.positions.size());
  const float d = 3.0f;
  const ClosedVolume v = closedVolume(cube, adjacency, {0, 1, 0, 0}, d);
  EXPECT_EQ(v.possibleSilhouetteEdges, 4u);
  EXPECT_EQ(v.sideTriangles, 8u);
  EXPECT_EQ(v.lightCapTriangles, 2u);
  EXPECT_EQ(v.darkCapTriangles, 10u);
  EXPECT_EQ(v.triangles.triangleCount(), 20u);
  EXPECT_EQ(unmatchedEdges(v.triangles), 0u);
  EXPECT_NEAR(signedVolume(asMesh(v.triangles)), 4.0 * (2.0 + d), 1e-4);  // positive: faces out
}

TEST(ClosedVolume, PointLightFiniteEqualsSidesPlusBothCaps) {
  // A point light off every axis, so no face is edge-on: the caps split the cube's 12 triangles.
  const Mesh cube = weldedCube();
  const EdgeAdjacency adjacency = buildEdgeAdjacency(cube.indices, cube.positions.size());
  const glm::vec4 light(2.5f, 3.0f, 3.5f, 1.0f);  // sees the +x, +y and +z faces
  const ClosedVolume v = closedVolume(cube, adjacency, light, 4.0f);
  EXPECT_EQ(v.possibleSilhouetteEdges, 6u);  // the hexagon around the three lit faces
  EXPECT_EQ(v.sideTriangles, 12u);
  EXPECT_EQ(v.lightCapTriangles, 6u);
  EXPECT_EQ(v.darkCapTriangles, 6u);
  EXPECT_EQ(unmatchedEdges(v.triangles), 0u);
  EXPECT_GT(signedVolume(asMesh(v.triangles)), 8.0);  // the cube and more, facing out
  const Mesh welded = weldByPosition(asMesh(v.triangles)).mesh;
  EXPECT_TRUE(buildEdgeAdjacency(welded.indices, welded.positions.size()).report.closedManifold());
}

TEST(ClosedVolume, ToInfinityTheDarkCapLiesAtWZeroAndStillCloses) {
  const Mesh cube = weldedCube();
  const EdgeAdjacency adjacency = buildEdgeAdjacency(cube.indices, cube.positions.size());
  const glm::vec4 light(2.5f, 3.0f, 3.5f, 1.0f);
  const ClosedVolume v = closedVolume(cube, adjacency, light, kInfinity);
  ASSERT_EQ(v.darkCapTriangles, 6u);
  const std::size_t darkBegin = 3 * (v.sideTriangles + v.lightCapTriangles);
  for (std::size_t i = 0; i < v.triangles.vertices.size(); ++i) {
    const float w = v.triangles.vertices[i].w;
    if (i >= darkBegin) {
      EXPECT_EQ(w, 0.0f);  // dark cap: at infinity
    } else if (i >= 3 * v.sideTriangles) {
      EXPECT_EQ(w, 1.0f);  // light cap: the faces themselves
    }
  }
  EXPECT_EQ(unmatchedEdges(v.triangles), 0u);
}

TEST(ClosedVolume, DirectionalToInfinityHasNoDarkCapTheSidesMeetAtOnePoint) {
  const Mesh cube = weldedCube();
  const EdgeAdjacency adjacency = buildEdgeAdjacency(cube.indices, cube.positions.size());
  const glm::vec4 light(0.3f, 1.0f, 0.2f, 0.0f);
  const ClosedVolume v = closedVolume(cube, adjacency, light, kInfinity);
  EXPECT_EQ(v.darkCapTriangles, 0u);
  for (std::size_t i = 0; i < 3 * v.sideTriangles; ++i)
    if (v.triangles.vertices[i].w == 0.0f) {
      EXPECT_EQ(v.triangles.vertices[i], -light);
    }
  EXPECT_EQ(unmatchedEdges(v.triangles), 0u);  // the sides' cone and the light cap close it
}

TEST(ClosedVolume, RefusesAnOpenMesh) {
  const Mesh square = makePlane(1.0f);
  const EdgeAdjacency adjacency = buildEdgeAdjacency(square.indices, square.positions.size());
  EXPECT_THROW(closedVolume(square, adjacency, {0, 1, 0, 0}, kInfinity), std::invalid_argument);
}

// ---- more than 255 nested volumes ---------------------------------------------------------------

TEST(NestedVolumes, ConvexCastersAreTheConvexOnes) {
  const auto convex = [](const Mesh& m) {
    const Mesh welded = weldByPosition(m).mesh;
    return isConvex(welded, buildEdgeAdjacency(welded.indices, welded.positions.size()));
  };
  EXPECT_TRUE(convex(makeCube(1.0f)));
  EXPECT_TRUE(convex(makeSphere(1.0f, 24, 12)));
  EXPECT_TRUE(convex(makeCylinder(0.5f, 1.0f, 16)));
  EXPECT_FALSE(convex(makeTorus(1.0f, 0.25f, 16, 8)));
  EXPECT_FALSE(convex(makeStairs(4, 1.0f, 0.2f, 0.3f)));
  Mesh two = makeCube(1.0f);  // two cubes apart in one mesh: convex at every edge, not one solid
  const Mesh other = makeCube(1.0f);
  for (const std::uint32_t i : other.indices) two.indices.push_back(i + std::uint32_t(two.positions.size()));
  for (const glm::vec3& p : other.positions) two.positions.push_back(p + glm::vec3(5, 0, 0));
  two.normals.insert(two.normals.end(), other.normals.begin(), other.normals.end());
  EXPECT_FALSE(convex(two));
  EXPECT_FALSE(convex(makePlane(1.0f))) << "open";
}

TEST(NestedVolumes, PiecesCountWhatTheWholeCasterCounts) {
  // A staircase of 12 steps (x and y in [-1.2, 1.2], rise = run, its noses on y = x + 0.2) lit
  // along the line of its noses, a hair below it: a point on that line below the stairs lies
  // in 12 nested volumes. The winding of the whole closed volume around a point equals the sum
  // of its pieces' windings, and never exceeds the nesting bound.
  const Mesh stairs = weldByPosition(makeStairs(12, 1.0f, 0.2f, 0.2f)).mesh;
  const EdgeAdjacency adjacency = buildEdgeAdjacency(stairs.indices, stairs.positions.size());
  const glm::vec4 light(60.0f, 60.15f, 0.1f, 1.0f);
  const float reach = 400.0f;
  const std::vector<bool> lit = facesLight(stairs, light);
  const ClosedVolume whole = closedVolume(stairs, adjacency, light, reach);
  const std::vector<std::vector<bool>> pieces = litFacePieces(lit, 5);
  std::size_t litCount = 0;
  for (bool l : lit) litCount += l;
  ASSERT_EQ(pieces.size(), (litCount + 4) / 5);
  std::vector<ClosedVolume> pieceVolumes;
  for (const auto& piece : pieces)
    pieceVolumes.push_back(closedVolume(stairs, adjacency, light, reach, piece));
  const std::size_t bound = nestingBound(litCount, whole.possibleSilhouetteEdges, false, true);
  int deepest = 0;
  for (int i = 0; i < 200; ++i) {
    // Half on the line of the light through the noses, half spread around the stairs.
    const double t = -3.0 + 0.0085 * i;
    const glm::dvec3 p = i % 2 ? glm::dvec3(t, t + 0.15, 0.1)
                               : glm::dvec3(-2.0 + 0.02 * i, -2.0 + 0.017 * i, -0.4 + 0.004 * i);
    // geometry/solid.h's winding number: how many times the closed volume winds around p.
    const int w = windingNumber(asMesh(whole.triangles), p);
    int sum = 0;
    for (const ClosedVolume& v : pieceVolumes) sum += windingNumber(asMesh(v.triangles), p);
    EXPECT_EQ(sum, w) << "at " << p.x << " " << p.y << " " << p.z;
    EXPECT_LE(w, int(bound));
    deepest = std::max(deepest, w);
  }
  EXPECT_EQ(deepest, 12) << "below the noses, inside every step's volume";
}

TEST(NestedVolumes, BoundsAndPlans) {
  EXPECT_EQ(nestingBound(0, 0, false, true), 0u);
  EXPECT_EQ(nestingBound(300, 40, true, false), 1u);
  EXPECT_EQ(nestingBound(300, 40, false, true), 20u);
  EXPECT_EQ(nestingBound(300, 40, false, false), 300u) << "a light inside the bounds: no half";
  EXPECT_EQ(nestingBound(7, 40, false, true), 7u);

  const CountPlan plain = countPlan(std::vector<std::size_t>(255, 1));
  EXPECT_FALSE(plain.fold);
  EXPECT_EQ(plain.groups, 1);
  const CountPlan folded = countPlan(std::vector<std::size_t>(1000, 1));
  EXPECT_TRUE(folded.fold);
  EXPECT_EQ(folded.groups, 8);  // ceil(1000 / 127)
  EXPECT_EQ(folded.group[126], 0);
  EXPECT_EQ(folded.group[127], 1);
  const CountPlan mixed = countPlan({100, 100, 100});
  EXPECT_EQ(mixed.group, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(countPlan({}).groups, 0);
  EXPECT_THROW(litFacePieces({true}, 0), std::invalid_argument);
  EXPECT_TRUE(litFacePieces({false, false}, 3).empty());
}

TEST(NestedVolumes, SilhouetteSeenFromTheLightBoundsATorus) {
  // A torus of 86,400 triangles lit from low beside it: the ray from the light through the far
  // tube's centre passes through the near tube first, so beyond the far tube a point lies inside
  // two nested volumes. The face count and half the silhouette edges allow hundreds; the
  // silhouette seen from the light must still allow those two, and no more than one count group's
  // 127, so that the torus is counted whole.
  const Mesh torus = weldByPosition(makeTorus(0.8f, 0.3f, 360, 120)).mesh;
  const EdgeAdjacency adjacency = buildEdgeAdjacency(torus.indices, torus.positions.size());
  const glm::vec4 light(0.0f, 0.6f, 3.0f, 1.0f);
  const std::vector<bool> lit = facesLight(torus, light);
  const std::vector<SilhouetteEdge> edges = possibleSilhouetteEdges(adjacency, lit);
  std::size_t litCount = 0;
  for (bool l : lit) litCount += l;
  EXPECT_GT(nestingBound(litCount, edges.size(), false, true), 127u) << "the old bound splits it";
  const std::size_t bound = projectedNestingBound(torus, lit, edges, light);
  EXPECT_LE(bound, 127u);
  const ClosedVolume whole = closedVolume(torus, adjacency, light, 400.0f);
  const Mesh volume = asMesh(whole.triangles);
  // From the light through (0, 0, -0.8), the far tube's centre: y = 0.6 - 0.6 s, z = 3 - 3.8 s.
  const glm::dvec3 beyond(0.0, 0.6 - 0.6 * 2.0, 3.0 - 3.8 * 2.0);
  EXPECT_EQ(windingNumber(volume, beyond), 2);
  EXPECT_GE(bound, 2u);
  // A directional light: the same bound along its rays, never below the nesting found.
  const glm::vec4 sun(0.0f, 0.2f, 1.0f, 0.0f);
  const std::vector<bool> sunLit = facesLight(torus, sun);
  const std::size_t sunBound = projectedNestingBound(torus, sunLit, possibleSilhouetteEdges(adjacency, sunLit), sun);
  EXPECT_GE(sunBound, 2u) << "a ray along -sun through both tubes";
  EXPECT_LE(sunBound, 127u);
  // A light in the hole's plane, beside the torus on the x axis: lit faces on both sides of it
  // along any axis, no plane shows them all, no bound.
  const glm::vec4 among(0.0f, 0.0f, 0.0f, 1.0f);
  const std::vector<bool> amongLit = facesLight(torus, among);
  EXPECT_EQ(projectedNestingBound(torus, amongLit, possibleSilhouetteEdges(adjacency, amongLit), among),
            std::numeric_limits<std::size_t>::max());
  EXPECT_EQ(projectedNestingBound(torus, std::vector<bool>(lit.size(), false), {}, light), 0u);
  EXPECT_THROW(projectedNestingBound(torus, {true}, edges, light), std::invalid_argument);
}

TEST(NestedVolumes, PiecesAreWholeRegionsOfLitFaces) {
  // The staircase of PiecesCountWhatTheWholeCasterCounts: each tread is a region of lit faces of
  // its own (its risers face away). Pieces that count at most 5 hold whole treads, so no edge
  // lies between lit faces of two pieces (where a side would hang from the lit surface), and the
  // pieces' windings still add up to the whole volume's, each within its piece's bound.
  const Mesh stairs = weldByPosition(makeStairs(12, 1.0f, 0.2f, 0.2f)).mesh;
  const EdgeAdjacency adjacency = buildEdgeAdjacency(stairs.indices, stairs.positions.size());
  const glm::vec4 light(60.0f, 60.15f, 0.1f, 1.0f);
  const float reach = 400.0f;
  const std::vector<bool> lit = facesLight(stairs, light);
  const std::vector<LitPiece> pieces = litFacePieces(stairs, adjacency, lit, light, 5);
  std::vector<int> pieceOf(lit.size(), -1);
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    EXPECT_GE(pieces[k].nesting, 1u);
    EXPECT_LE(pieces[k].nesting, 5u);
    for (std::size_t t = 0; t < lit.size(); ++t)
      if (pieces[k].lit[t]) {
        EXPECT_TRUE(lit[t]);
        EXPECT_EQ(pieceOf[t], -1) << "face " << t << " in two pieces";
        pieceOf[t] = int(k);
      }
  }
  for (std::size_t t = 0; t < lit.size(); ++t) EXPECT_EQ(pieceOf[t] >= 0, bool(lit[t])) << "face " << t;
  for (const Edge& e : adjacency.edges)
    if (e.face1 >= 0 && lit[std::size_t(e.face0)] && lit[std::size_t(e.face1)]) {
      EXPECT_EQ(pieceOf[std::size_t(e.face0)], pieceOf[std::size_t(e.face1)]) << "an edge between two pieces";
    }
  EXPECT_LE(pieces.size(), 4u) << "12 treads of bound 1, 5 to a piece: 3 pieces (a tread may have more faces)";
  const ClosedVolume whole = closedVolume(stairs, adjacency, light, reach);
  std::vector<Mesh> volumes;
  for (const LitPiece& piece : pieces) volumes.push_back(asMesh(closedVolume(stairs, adjacency, light, reach, piece.lit).triangles));
  int deepest = 0;
  for (int i = 0; i < 200; ++i) {
    const double t = -3.0 + 0.0085 * i;
    const glm::dvec3 p = i % 2 ? glm::dvec3(t, t + 0.15, 0.1)
                               : glm::dvec3(-2.0 + 0.02 * i, -2.0 + 0.017 * i, -0.4 + 0.004 * i);
    const int w = windingNumber(asMesh(whole.triangles), p);
    int sum = 0;
    for (std::size_t k = 0; k < volumes.size(); ++k) {
      const int wk = windingNumber(volumes[k], p);
      EXPECT_LE(wk, int(pieces[k].nesting));
      sum += wk;
    }
    EXPECT_EQ(sum, w) << "at " << p.x << " " << p.y << " " << p.z;
    deepest = std::max(deepest, w);
  }
  EXPECT_EQ(deepest, 12);
  EXPECT_THROW(litFacePieces(stairs, adjacency, lit, light, 0), std::invalid_argument);
}

TEST(ShadowVolume, FacesTurnedFromLightAreThoseWhoseSeenSideTheLightMisses) {
  // A cube of half size 0.5 (12 triangles), the light above it, the eye in front of it. The front
  // face (+z) faces away from the light and towards the eye. The top face faces the light, but
  // the eye lies below its plane and sees its other side. The bottom, back and x faces have the
  // light and the eye on the same side of their planes (behind them).
  const Mesh cube = weldByPosition(makeCube(0.5f)).mesh;
  const glm::vec4 light(0.0f, 5.0f, 0.0f, 1.0f), eye(0.0f, 0.0f, 5.0f, 1.0f);
  const std::vector<std::uint32_t> turned = facesTurnedFromLight(cube, light, eye);
  ASSERT_EQ(turned.size(), 12u) << "two faces of two triangles";
  for (std::size_t t = 0; t < turned.size() / 3; ++t) {
    const glm::vec3 a = cube.positions[turned[3 * t]], b = cube.positions[turned[3 * t + 1]],
                    c = cube.positions[turned[3 * t + 2]];
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    EXPECT_TRUE(n == glm::vec3(0, 0, 1) || n == glm::vec3(0, 1, 0)) << n.x << " " << n.y << " " << n.z;
  }
  // A parallel view looking down: the top and the bottom have the eye on the light's side, the
  // other faces are edge-on to the eye.
  const std::vector<std::uint32_t> fromAbove = facesTurnedFromLight(cube, light, glm::vec4(0, 1, 0, 0));
  EXPECT_TRUE(fromAbove.empty()) << "the eye on the light's side of every face's plane";
}
