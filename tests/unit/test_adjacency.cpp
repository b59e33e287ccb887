#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <vector>

#include "geometry/adjacency.h"

namespace {

using stencil::Edge;
using stencil::EdgeAdjacency;
using Indices = std::vector<std::uint32_t>;

std::optional<Edge> findEdge(const EdgeAdjacency& adj, std::uint32_t a, std::uint32_t b) {
  for (const Edge& e : adj.edges) {
    if ((e.v0 == a && e.v1 == b) || (e.v0 == b && e.v1 == a)) return e;
  }
  return std::nullopt;
}

// Does triangle `face` contain the directed edge from -> to?
bool walks(const Indices& idx, std::int32_t face, std::uint32_t from, std::uint32_t to) {
  for (int k = 0; k < 3; ++k) {
    if (idx[3 * face + k] == from && idx[3 * face + (k + 1) % 3] == to) return true;
  }
  return false;
}

// Checks the documented face0/face1 directions on every edge, skipping the
// edges the report says may break them.
void expectDirectionsHold(const Indices& idx, const EdgeAdjacency& adj) {
  for (std::size_t e = 0; e < adj.edges.size(); ++e) {
    const Edge& edge = adj.edges[e];
    EXPECT_TRUE(walks(idx, edge.face0, edge.v0, edge.v1)) << "edge " << e;
    const auto flagged = [&](const std::vector<std::uint32_t>& list) {
      return std::find(list.begin(), list.end(), e) != list.end();
    };
    if (edge.face1 >= 0 && !flagged(adj.inconsistentEdgeIndices) && !flagged(adj.nonManifoldEdgeIndices)) {
      EXPECT_TRUE(walks(idx, edge.face1, edge.v1, edge.v0)) << "edge " << e;
    }
    EXPECT_EQ(edge.face1 < 0, flagged(adj.borderEdgeIndices)) << "edge " << e;
  }
}

TEST(Adjacency, SingleTriangleHasThreeBorderEdges) {
  const Indices idx = {0, 1, 2};
  const EdgeAdjacency adj = stencil::buildEdgeAdjacency(idx, 3);
  ASSERT_EQ(adj.edges.size(), 3u);
  EXPECT_EQ(adj.report.borderEdges, 3u);
  EXPECT_EQ(adj.borderEdgeIndices.size(), 3u);
  EXPECT_FALSE(adj.report.closedManifold());
  // The only face walks 0->1, 1->2, 2->0, so those are the edge directions.
  EXPECT_EQ(adj.edges[0].v0, 0u);
  EXPECT_EQ(adj.edges[0].v1, 1u);
  EXPECT_EQ(adj.edges[2].v0, 2u);
  EXPECT_EQ(adj.edges[2].v1, 0u);
  for (const Edge& e : adj.edges) {
    EXPECT_EQ(e.face0, 0);
    EXPECT_EQ(e.face1, -1);
  }
  expectDirectionsHold(idx, adj);
}

TEST(Adjacency, TwoTrianglesShareOneEdge) {
  // Quad 0-1-2-3 split along 0-2: the diagonal is interior, the 4 sides border.
  const Indices idx = {0, 1, 2, 0, 2, 3};
  const EdgeAdjacency adj = stencil::buildEdgeAdjacency(idx, 4);
  EXPECT_EQ(adj.edges.size(), 5u);
  EXPECT_EQ(adj.report.borderEdges, 4u);
  EXPECT_EQ(adj.report.inconsistentEdges, 0u);
  EXPECT_EQ(adj.report.nonManifoldEdges, 0u);
  const std::optional<Edge> diagonal = findEdge(adj, 0, 2);
  ASSERT_TRUE(diagonal);
  // Triangle 0 walks 2->0 first (it saw the edge first), triangle 1 walks 0->2.
  EXPECT_EQ(diagonal->v0, 2u);
  EXPECT_EQ(diagonal->v1, 0u);
  EXPECT_EQ(diagonal->face0, 0);
  EXPECT_EQ(diagonal->face1, 1);
  expectDirectionsHold(idx, adj);
}

TEST(Adjacency, TetrahedronIsClosed) {
  // 4 faces, each pair sharing one edge: C(4,2) = 6 edges, none on a border.
  const Indices idx = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  const EdgeAdjacency adj = stencil::buildEdgeAdjacency(idx, 4);
  EXPECT_EQ(adj.edges.size(), 6u);
  EXPECT_EQ(adj.report.borderEdges, 0u);
  EXPECT_EQ(adj.report.nonManifoldEdges, 0u);
  EXPECT_EQ(adj.report.inconsistentEdges, 0u);
  EXPECT_EQ(adj.report.degenerateTriangles, 0u);
  EXPECT_TRUE(adj.report.closedManifold());
  for (const Edge& e : adj.edges) {
    EXPECT_GE(e.face1, 0);
    EXPECT_NE(e.face0, e.face1);
  }
  expectDirectionsHold(idx, adj);
}

TEST(Adjacency, TetrahedronWithOneFaceFlipped) {
  // Flipping one face reverses its 3 edges against their neighbours.
  const Indices idx = {0, 1, 2, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  const EdgeAdjacency adj = stencil::buildEdgeAdjacency(idx, 4);
  EXPECT_EQ(adj.edges.size(), 6u);
  EXPECT_EQ(adj.report.borderEdges, 0u);
  EXPECT_EQ(adj.report.inconsistentEdges, 3u);
  EXPECT_FALSE(adj.report.closedManifold());
  for (std::uint32_t e : adj.inconsistentEdgeIndices) {
    const Edge& edge = adj.edges[e];
    // Both faces walk the same way, and face 0 is one of them.
    EXPECT_TRUE(walks(idx, edge.face0, edge.v0, edge.v1));
    EXPECT_TRUE(walks(idx, edge.face1, edge.v0, edge.v1));
    EXPECT_TRUE(edge.face0 == 0 || edge.face1 == 0);
  }
  expectDirectionsHold(idx, adj);
}

TEST(Adjacency, ThreeTrianglesOnOneEdgeAreNonManifold) {
  // A "book" of three pages on spine 0-1.
  const Indices idx = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  const EdgeAdjacency adj = stencil::buildEdgeAdjacency(idx, 5);
  EXPECT_EQ(adj.report.nonManifoldEdges, 1u);
  ASSERT_EQ(adj.nonManifoldEdgeIndices.size(), 1u);
  const Edge& spine = adj.edges[adj.nonManifoldEdgeIndices[0]];
  EXPECT_EQ(std::min(spine.v0, spine.v1), 0u);
  EXPECT_EQ(std::max(spine.v0, spine.v1), 1u);
  // Two of the three faces are kept: the first, and the first one opposed to it.
  EXPECT_EQ(spine.face0, 0);
  EXPECT_EQ(spine.face1, 1);
  // Each page's two other edges are borders; the spine is not double counted.
  EXPECT_EQ(adj.report.borderEdges, 6u);
  EXPECT_EQ(adj.report.inconsistentEdges, 0u);
  EXPECT_FALSE(adj.report.closedManifold());
  expectDirectionsHold(idx, adj);
}

TEST(Adjacency, NonManifoldPrefersAnOpposedSecondFace) {
  // Faces 0 and 1 both walk 0->1; face 2 walks 1->0 and becomes face1.
  const Indices idx = {0, 1, 2, 0, 1, 3, 1, 0, 4};
  const EdgeAdjacency adj = stencil::buildEdgeAdjacency(idx, 5);
  ASSERT_EQ(adj.nonManifoldEdgeIndices.size(), 1u);
  const Edge& spine = adj.edges[adj.nonManifoldEdgeIndices[0]];
  EXPECT_EQ(spine.face0, 0);
  EXPECT_EQ(spine.face1, 2);
}

TEST(Adjacency, QuadWithOneTriangleFlipped) {
  // The quad's second triangle wound 0,3,2 instead of 0,2,3. Triangle 0
  // (0,1,2) walks the diagonal 2->0, and so does triangle 1 (0,3,2): the
  // same direction, so the winding flips across it.
  const Indices idx = {0, 1, 2, 0, 3, 2};
  const EdgeAdjacency adj = stencil::buildEdgeAdjacency(idx, 4);
  EXPECT_EQ(adj.report.inconsistentEdges, 1u);
  ASSERT_EQ(adj.inconsistentEdgeIndices.size(), 1u);
  const Edge& diagonal = adj.edges[adj.inconsistentEdgeIndices[0]];
  EXPECT_EQ(diagonal.v0, 2u);
  EXPECT_EQ(diagonal.v1, 0u);
  EXPECT_EQ(diagonal.face0, 0);
  EXPECT_EQ(diagonal.face1, 1);
  EXPECT_EQ(adj.report.borderEdges, 4u);
  EXPECT_EQ(adj.report.nonManifoldEdges, 0u);
  expectDirectionsHold(idx, adj);
}

TEST(Adjacency, DegenerateTrianglesAreCountedAndSkipped) {
  // Tetrahedron plus two collapsed triangles: they add no edges.
  const Indices idx = {0, 2, 1, 0, 1, 3, 3, 3, 1, 0, 3, 2, 1, 2, 3, 2, 0, 2};
  const EdgeAdjacency adj = stencil::buildEdgeAdjacency(idx, 4);
  EXPECT_EQ(adj.report.degenerateTriangles, 2u);
  EXPECT_EQ(adj.degenerateTriangleIndices, (std::vector<std::uint32_t>{2, 5}));
  EXPECT_EQ(adj.edges.size(), 6u);
  EXPECT_TRUE(adj.report.closedManifold());
  // Face numbers still count the skipped triangles: the last real face is 4.
  std::int32_t highest = 0;
  for (const Edge& e : adj.edges) highest = std::max({highest, e.face0, e.face1});
  EXPECT_EQ(highest, 4);
  expectDirectionsHold(idx, adj);
}

TEST(Adjacency, EmptyInput) {
  const EdgeAdjacency adj = stencil::buildEdgeAdjacency({}, 0);
  EXPECT_TRUE(adj.edges.empty());
  EXPECT_TRUE(adj.report.closedManifold());  // vacuously
}

TEST(Adjacency, InvalidInputThrows) {
  EXPECT_THROW(stencil::buildEdgeAdjacency({0, 1}, 3), std::invalid_argument);
  EXPECT_THROW(stencil::buildEdgeAdjacency({0, 1, 2, 0}, 3), std::invalid_argument);
  EXPECT_THROW(stencil::buildEdgeAdjacency({0, 1, 3}, 3), std::invalid_argument);
  EXPECT_THROW(stencil::buildEdgeAdjacency({0, 1, 2}, 0), std::invalid_argument);
}

TEST(Adjacency, LargeGridIsLinear) {
  // n x n quad grid, two triangles per quad: (n+1)^2 vertices,
  // n(n+1) horizontal + n(n+1) vertical + n^2 diagonal edges, 4n on the border.
  const std::uint32_t n = 300;
  Indices idx;
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t j = 0; j < n; ++j) {
      const std::uint32_t a = i * (n + 1) + j, b = a + 1, c = a + n + 1, d = c + 1;
      idx.insert(idx.end(), {a, c, d, a, d, b});
    }
  }
  const EdgeAdjacency adj = stencil::buildEdgeAdjacency(idx, (n + 1) * (n + 1));
  EXPECT_EQ(adj.edges.size(), std::size_t{2} * n * (n + 1) + std::size_t{n} * n);
  EXPECT_EQ(adj.report.borderEdges, 4u * n);
  EXPECT_EQ(adj.report.inconsistentEdges, 0u);
  EXPECT_EQ(adj.report.nonManifoldEdges, 0u);
}

}  // namespace
