#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <set>
#include <stdexcept>
#include <tuple>

#include "geometry/shapes.h"
#include "geometry/weld.h"

namespace {

using stencil::Mesh;
using stencil::WeldResult;

// Every input vertex maps to a welded vertex at the same place, and the
// welded index buffer is the input one pushed through remap.
void expectConsistentRemap(const Mesh& in, const WeldResult& out, float tolerance = 0.0f) {
  ASSERT_EQ(out.remap.size(), in.positions.size());
  for (std::size_t i = 0; i < in.positions.size(); ++i) {
    ASSERT_LT(out.remap[i], out.mesh.positions.size());
    if (tolerance == 0.0f) {
      EXPECT_EQ(out.mesh.positions[out.remap[i]], in.positions[i]) << "vertex " << i;
    } else {
      EXPECT_LE(glm::distance(out.mesh.positions[out.remap[i]], in.positions[i]), tolerance)
          << "vertex " << i;
    }
  }
  ASSERT_EQ(out.mesh.indices.size(), in.indices.size());
  for (std::size_t k = 0; k < in.indices.size(); ++k)
    EXPECT_EQ(out.mesh.indices[k], out.remap[in.indices[k]]);
}

std::size_t distinctPositions(const Mesh& m) {
  std::set<std::tuple<float, float, float>> seen;
  for (const glm::vec3& p : m.positions)
    seen.emplace(p.x + 0.0f, p.y + 0.0f, p.z + 0.0f);  // +0.0f folds -0 into +0
  return seen.size();
}

TEST(Weld, CubeCollapsesToEightCorners) {
  const Mesh cube = stencil::makeCube(1.0f);
  const WeldResult w = stencil::weldByPosition(cube);
  EXPECT_EQ(w.mesh.positions.size(), 8u);  // a cube has 8 corners
  EXPECT_EQ(w.mesh.triangleCount(), 12u);
  expectConsistentRemap(cube, w);
  for (std::size_t i = 0; i < w.mesh.positions.size(); ++i) {
    const glm::vec3 p = w.mesh.positions[i];
    EXPECT_EQ(glm::abs(p), glm::vec3(1.0f));
    // Each corner merges one normal from each of its 3 faces, (+-1,0,0) etc.,
    // so the average points along the diagonal through the corner.
    EXPECT_NEAR(glm::distance(w.mesh.normals[i], p / std::sqrt(3.0f)), 0.0f, 1e-6f);
  }
}

TEST(Weld, EveryShapeWeldsToItsDistinctPositions) {
  for (const Mesh& m : {stencil::makePlane(1.0f, 3), stencil::makeCube(0.5f), stencil::makeSphere(1.0f, 9, 5),
                        stencil::makeTorus(1.0f, 0.3f, 7, 5), stencil::makeCylinder(1.0f, 2.0f, 11),
                        stencil::makeCone(1.0f, 2.0f, 13)}) {
    const WeldResult w = stencil::weldByPosition(m);
    EXPECT_EQ(w.mesh.positions.size(), distinctPositions(m));
    EXPECT_EQ(w.mesh.normals.size(), w.mesh.positions.size());
    for (const glm::vec3& n : w.mesh.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    expectConsistentRemap(m, w);
  }
}

TEST(Weld, NegativeZeroEqualsPositiveZero) {
  Mesh m;
  m.positions = {{0.0f, 1.0f, 0.0f}, {-0.0f, 1.0f, -0.0f}, {1.0f, 0.0f, 0.0f}, {1.0f, -0.0f, 0.0f}};
  m.indices = {0, 2, 1, 1, 3, 0};
  const WeldResult w = stencil::weldByPosition(m);
  EXPECT_EQ(w.mesh.positions.size(), 2u);
  EXPECT_EQ(w.remap, (std::vector<std::uint32_t>{0, 0, 1, 1}));
  EXPECT_TRUE(w.mesh.normals.empty());  // none in, none out
  expectConsistentRemap(m, w);
}

TEST(Weld, KeepsFirstOccurrenceOrder) {
  Mesh m;
  m.positions = {{2, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {1, 0, 0}};
  const WeldResult w = stencil::weldByPosition(m);
  EXPECT_EQ(w.mesh.positions, (std::vector<glm::vec3>{{2, 0, 0}, {1, 0, 0}, {3, 0, 0}}));
  EXPECT_EQ(w.remap, (std::vector<std::uint32_t>{0, 1, 0, 2, 1}));
}

TEST(Weld, MeshWithoutDuplicatesIsUnchanged) {
  // The UV sphere has one vertex per pole and no seam, so nothing to merge.
  const Mesh sphere = stencil::makeSphere(1.0f, 16, 8);
  const WeldResult w = stencil::weldByPosition(sphere);
  EXPECT_EQ(w.mesh.positions, sphere.positions);
  EXPECT_EQ(w.mesh.indices, sphere.indices);
  ASSERT_EQ(w.mesh.normals.size(), sphere.normals.size());
  for (std::size_t i = 0; i < sphere.normals.size(); ++i) {
    EXPECT_NEAR(glm::distance(w.mesh.normals[i], sphere.normals[i]), 0.0f, 1e-6f);
  }
  for (std::size_t i = 0; i < w.remap.size(); ++i) EXPECT_EQ(w.remap[i], i);
}

TEST(Weld, CancellingNormalsKeepTheFirst) {
  // A two-sided quad corner: +y and -y sum to zero, no direction to average.
  Mesh m;
  m.positions = {{0, 0, 0}, {0, 0, 0}};
  m.normals = {{0, 1, 0}, {0, -1, 0}};
  const WeldResult w = stencil::weldByPosition(m);
  ASSERT_EQ(w.mesh.normals.size(), 1u);
  EXPECT_EQ(w.mesh.normals[0], glm::vec3(0, 1, 0));
}

TEST(Weld, DegenerateTrianglesAreKept) {
  // Welding two corners of a triangle together makes it degenerate; it stays
  // in the index buffer so triangle numbers still line up with the input.
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}};
  m.indices = {0, 1, 2};
  const WeldResult w = stencil::weldByPosition(m);
  EXPECT_EQ(w.mesh.indices, (std::vector<std::uint32_t>{0, 1, 1}));
}

TEST(Weld, RejectsInvalidInput) {
  Mesh m = stencil::makeCube(1.0f);
  m.positions[3].x = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(stencil::weldByPosition(m), std::invalid_argument);
  EXPECT_THROW(stencil::weldByPosition(m, 0.1f), std::invalid_argument);

  Mesh badIndex = stencil::makeCube(1.0f);
  badIndex.indices[0] = 24;
  EXPECT_THROW(stencil::weldByPosition(badIndex), std::invalid_argument);
}

TEST(WeldTolerance, MergesWithinToleranceOnly) {
  Mesh m;
  // 0.0999 and 0.1001 straddle a grid line at tolerance 0.01 (cells 9 and 10),
  // so this also checks the neighbour-cell search. 0.1 -> 0.115 is 0.015 apart.
  m.positions = {{0.0999f, 0, 0}, {0.1001f, 0, 0}, {0.115f, 0, 0}, {0.0999f, 0.005f, -0.005f}};
  const WeldResult w = stencil::weldByPosition(m, 0.01f);
  EXPECT_EQ(w.remap, (std::vector<std::uint32_t>{0, 0, 1, 0}));
  EXPECT_EQ(w.mesh.positions[0], m.positions[0]);  // the first occurrence is kept
  expectConsistentRemap(m, w, 0.01f);
}

TEST(WeldTolerance, RepairsJitteredCube) {
  // Nudge vertex i by (i+1) micro-units so no two copies of a corner are
  // equal (at most ~4e-5 apart): the exact weld keeps all 24, a 1e-4
  // tolerance finds the 8 corners again.
  Mesh cube = stencil::makeCube(1.0f);
  for (std::size_t i = 0; i < cube.positions.size(); ++i) {
    const float jitter = 1e-6f * static_cast<float>(i + 1);
    cube.positions[i] += glm::vec3(jitter, -jitter, 0.5f * jitter);
  }
  EXPECT_EQ(stencil::weldByPosition(cube).mesh.positions.size(), 24u);
  const WeldResult w = stencil::weldByPosition(cube, 1e-4f);
  EXPECT_EQ(w.mesh.positions.size(), 8u);
  expectConsistentRemap(cube, w, 1e-4f);
}

TEST(WeldTolerance, ZeroIsExactAndBadTolerancesThrow) {
  const Mesh cube = stencil::makeCube(1.0f);
  EXPECT_EQ(stencil::weldByPosition(cube, 0.0f).remap, stencil::weldByPosition(cube).remap);
  EXPECT_THROW(stencil::weldByPosition(cube, -0.1f), std::invalid_argument);
  EXPECT_THROW(stencil::weldByPosition(cube, std::numeric_limits<float>::quiet_NaN()), std::invalid_argument);
  EXPECT_THROW(stencil::weldByPosition(cube, std::numeric_limits<float>::infinity()), std::invalid_argument);
  Mesh far = cube;
  far.positions[0] = glm::vec3(1e30f);
  EXPECT_THROW(stencil::weldByPosition(far, 1e-20f), std::invalid_argument);  // 1e50 cells
}

TEST(Weld, LargeMeshIsFast) {
  // Hash-based, so a quarter-million duplicated vertices weld quickly; a
  // quadratic weld would take minutes here.
  const Mesh sphere = stencil::makeSphere(1.0f, 512, 256);
  Mesh doubled = sphere;
  doubled.positions.insert(doubled.positions.end(), sphere.positions.begin(), sphere.positions.end());
  doubled.normals.insert(doubled.normals.end(), sphere.normals.begin(), sphere.normals.end());
  const WeldResult w = stencil::weldByPosition(doubled);
  EXPECT_EQ(w.mesh.positions.size(), sphere.positions.size());
  EXPECT_EQ(w.remap[sphere.positions.size() + 17], 17u);
}

}  // namespace
