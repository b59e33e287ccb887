// Scenes: casters prepared for shadow volumes (welded, degenerate triangles dropped, problems
// reported).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "geometry/scene.h"
#include "geometry/shapes.h"
#include "geometry/weld.h"

namespace {

using namespace stencil;

bool mentions(const CasterReport& report, const std::string& text) {
  return std::any_of(report.messages.begin(), report.messages.end(),
                     [&](const std::string& m) { return m.find(text) != std::string::npos; });
}

// The closed tetrahedron (0,0,0) (1,0,0) (0,1,0) (0,0,1), counter-clockwise seen from outside.
Mesh tetrahedron() {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  return m;
}

TEST(PrepareCaster, WeldsTheCubesSplitVertices) {
  const Mesh cube = makeCube(1.0f);
  ASSERT_EQ(cube.positions.size(), 24u);
  const PreparedCaster c = prepareCaster(cube);
  EXPECT_EQ(c.report.inputVertices, 24u);
  EXPECT_EQ(c.report.weldedVertices, 8u);
  EXPECT_EQ(c.mesh.positions.size(), 8u);
  EXPECT_EQ(c.mesh.triangleCount(), 12u);
  EXPECT_TRUE(c.mesh.normals.empty());
  EXPECT_EQ(c.adjacency.edges.size(), 18u);  // 12 cube edges + 6 face diagonals
  EXPECT_TRUE(c.report.closedManifold());
  EXPECT_TRUE(mentions(c.report, "welded 24 vertices into 8 (vertices split at seams)"))
      << c.report.messages.front();
  EXPECT_EQ(c.report.messages.size(), 1u);
}

TEST(PrepareCaster, AClosedWeldedMeshHasNothingToSay) {
  const PreparedCaster c = prepareCaster(tetrahedron());
  EXPECT_TRUE(c.report.closedManifold());
  EXPECT_TRUE(c.report.messages.empty());
  EXPECT_EQ(c.mesh.triangleCount(), 4u);
}

TEST(PrepareCaster, DropsRepeatedIndexAndCollinearTriangles) {
  Mesh m = tetrahedron();
  // A repeated index, and three distinct vertices on one line (the midpoint of edge 0-1).
  m.positions.push_back({0.5f, 0.0f, 0.0f});
  m.indices.insert(m.indices.end(), {1, 1, 2, 0, 4, 1});
  const PreparedCaster c = prepareCaster(m);
  EXPECT_EQ(c.report.droppedDegenerate, 2u);
  EXPECT_EQ(c.mesh.triangleCount(), 4u);
  EXPECT_TRUE(c.report.closedManifold());  // the extra vertex is unused; the tetrahedron stays closed
  EXPECT_TRUE(mentions(c.report, "dropped 2 degenerate triangles"));
}

TEST(PrepareCaster, DegenerateTrianglesInsideAClosedMeshLeaveItClosed) {
  // A cube with a zero-area triangle along each edge of one face: welded, it must stay closed.
  Mesh cube = weldByPosition(makeCube(1.0f)).mesh;
  const std::uint32_t a = cube.indices[0], b = cube.indices[1];
  cube.indices.insert(cube.indices.end(), {a, b, b, b, a, a});
  const PreparedCaster c = prepareCaster(cube);
  EXPECT_EQ(c.report.droppedDegenerate, 2u);
  EXPECT_TRUE(c.report.closedManifold());
}

TEST(PrepareCaster, CountsAndReportsAnOpenMeshsBorderEdges) {
  Mesh m = tetrahedron();
  m.indices.resize(9);  // one face removed: its three edges are borders
  const PreparedCaster c = prepareCaster(m);
  EXPECT_EQ(c.report.borderEdges, 3u);
  EXPECT_TRUE(c.report.usable());
  EXPECT_FALSE(c.report.closedManifold());
  EXPECT_TRUE(mentions(c.report, "open: 3 border edges extrude as silhouette edges"));

  const PreparedCaster plane = prepareCaster(makePlane(1.0f, 2));
  EXPECT_EQ(plane.report.borderEdges, 8u);
  EXPECT_TRUE(plane.report.usable());
}

TEST(PrepareCaster, AnEdgeWithThreeFacesIsReportedAndNotUsable) {
  Mesh m = tetrahedron();
  m.positions.push_back({1, 1, 1});
  m.indices.insert(m.indices.end(), {1, 2, 4});  // a fin on edge 1-2
  const PreparedCaster c = prepareCaster(m);
  EXPECT_EQ(c.report.nonManifoldEdges, 1u);
  EXPECT_FALSE(c.report.usable());
  EXPECT_FALSE(c.report.closedManifold());
  EXPECT_TRUE(mentions(c.report, "not two-manifold: 1 edge shared by three or more faces"));
}

TEST(PrepareCaster, InconsistentWindingIsReportedAndNotUsable) {
  Mesh m = tetrahedron();
  std::swap(m.indices[10], m.indices[11]);  // the last face turned round: its three edges
  const PreparedCaster c = prepareCaster(m);
  EXPECT_EQ(c.report.inconsistentEdges, 3u);
  EXPECT_FALSE(c.report.usable());
  EXPECT_TRUE(mentions(c.report, "inconsistently wound: 3 edges walked the same way by both faces"));
}

TEST(PrepareCaster, RefusesABrokenMesh) {
  Mesh m = tetrahedron();
  m.indices.push_back(0);
  EXPECT_THROW(prepareCaster(m), std::invalid_argument);
}

}  // namespace
