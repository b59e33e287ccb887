#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <stdexcept>

#include "geometry/mesh.h"
#include "geometry/shapes.h"

namespace {

using stencil::Mesh;

// Right-angled corner tetrahedron on the axes; each face wound so
// cross(b - a, c - a) points away from the opposite vertex.
Mesh cornerTetrahedron(float s) {
  Mesh m;
  m.positions = {{0, 0, 0}, {s, 0, 0}, {0, s, 0}, {0, 0, s}};
  m.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  return m;
}

glm::vec3 faceNormal(const Mesh& m, std::size_t t) {
  const glm::vec3 a = m.positions[m.indices[3 * t]];
  const glm::vec3 b = m.positions[m.indices[3 * t + 1]];
  const glm::vec3 c = m.positions[m.indices[3 * t + 2]];
  return glm::cross(b - a, c - a);
}

// Every vertex normal agrees with the winding of the triangles using it.
void expectNormalsMatchWinding(const Mesh& m) {
  for (std::size_t t = 0; t < m.triangleCount(); ++t) {
    const glm::vec3 n = faceNormal(m, t);
    for (int k = 0; k < 3; ++k) {
      EXPECT_GT(glm::dot(n, m.normals[m.indices[3 * t + k]]), 0.0f) << "triangle " << t;
    }
  }
}

TEST(Mesh, TriangleCountIsIndicesOverThree) {
  EXPECT_EQ(Mesh{}.triangleCount(), 0u);
  EXPECT_EQ(cornerTetrahedron(1).triangleCount(), 4u);  // 12 indices
}

TEST(Mesh, ValidateRejectsBrokenMeshes) {
  Mesh m = cornerTetrahedron(1);
  EXPECT_NO_THROW(stencil::validateMesh(m));

  Mesh partial = m;
  partial.indices.push_back(0);
  EXPECT_THROW(stencil::validateMesh(partial), std::invalid_argument);

  Mesh outOfRange = m;
  outOfRange.indices[5] = 4;  // only vertices 0..3 exist
  EXPECT_THROW(stencil::validateMesh(outOfRange), std::invalid_argument);

  Mesh badNormals = m;
  badNormals.normals.assign(3, glm::vec3(0, 1, 0));  // 3 normals for 4 positions
  EXPECT_THROW(stencil::validateMesh(badNormals), std::invalid_argument);
}

TEST(Mesh, FiniteChecksFindNaNAndInf) {
  Mesh m = stencil::makeCube(1.0f);
  EXPECT_TRUE(stencil::allFinite(m));
  EXPECT_FALSE(stencil::firstNonFiniteVertex(m).has_value());

  Mesh withNaN = m;
  withNaN.positions[5].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(stencil::allFinite(withNaN));
  EXPECT_EQ(stencil::firstNonFiniteVertex(withNaN), 5u);

  Mesh withInf = m;
  withInf.positions[9].z = -std::numeric_limits<float>::infinity();
  EXPECT_FALSE(stencil::allFinite(withInf));
  EXPECT_EQ(stencil::firstNonFiniteVertex(withInf), 9u);

  // Normals count too, and the earliest bad vertex wins.
  Mesh both = m;
  both.positions[7].x = std::numeric_limits<float>::quiet_NaN();
  both.normals[2].x = std::numeric_limits<float>::infinity();
  EXPECT_FALSE(stencil::allFinite(both));
  EXPECT_EQ(stencil::firstNonFiniteVertex(both), 2u);
}

TEST(Mesh, SignedVolumeOfTetrahedronAndCube) {
  // Corner tetrahedron: s^3 / 6. Cube of half extent h: (2h)^3.
  EXPECT_NEAR(stencil::signedVolume(cornerTetrahedron(3.0f)), 27.0 / 6.0, 1e-9);
  EXPECT_NEAR(stencil::signedVolume(stencil::makeCube(0.5f)), 1.0, 1e-9);
  EXPECT_NEAR(stencil::signedVolume(stencil::makeCube(2.0f)), 64.0, 1e-9);
}

TEST(Mesh, SignedVolumeFlipsWithWinding) {
  Mesh m = cornerTetrahedron(1.0f);
  for (std::size_t t = 0; t < m.indices.size(); t += 3) std::swap(m.indices[t + 1], m.indices[t + 2]);
  EXPECT_NEAR(stencil::signedVolume(m), -1.0 / 6.0, 1e-9);
}

TEST(Mesh, SignedVolumeIgnoresWhereTheClosedMeshIs) {
  // Closed mesh: the origin of the tetrahedra fan cancels out.
  const Mesh moved =
      stencil::transformed(stencil::makeCube(1.0f), glm::translate(glm::mat4(1.0f), {5, -7, 3}));
  EXPECT_NEAR(stencil::signedVolume(moved), 8.0, 1e-4);
}

TEST(Transformed, TranslationMovesPositionsKeepsNormals) {
  const Mesh cube = stencil::makeCube(1.0f);
  const glm::vec3 offset(1.5f, -2.0f, 0.25f);
  const Mesh moved = stencil::transformed(cube, glm::translate(glm::mat4(1.0f), offset));
  ASSERT_EQ(moved.positions.size(), cube.positions.size());
  for (std::size_t i = 0; i < cube.positions.size(); ++i) {
    EXPECT_EQ(moved.positions[i], cube.positions[i] + offset);
    EXPECT_EQ(moved.normals[i], cube.normals[i]);
  }
  EXPECT_EQ(moved.indices, cube.indices);
}

TEST(Transformed, UniformScaleScalesVolumeByCube) {
  const Mesh sphere = stencil::makeSphere(1.0f, 16, 8);
  const double before = stencil::signedVolume(sphere);
  const Mesh scaled = stencil::transformed(sphere, glm::scale(glm::mat4(1.0f), glm::vec3(3.0f)));
  EXPECT_NEAR(stencil::signedVolume(scaled), 27.0 * before, 27.0 * before * 1e-5);
}

TEST(Transformed, MirrorKeepsMeshOutward) {
  // det = -1: without the winding flip the volume would come out negative.
  for (const glm::vec3 mirror : {glm::vec3(-1, 1, 1), glm::vec3(1, -1, 1), glm::vec3(-1, -1, -1)}) {
    const Mesh sphere = stencil::makeSphere(1.0f, 12, 6);
    const Mesh mirrored = stencil::transformed(sphere, glm::scale(glm::mat4(1.0f), mirror));
    EXPECT_NEAR(stencil::signedVolume(mirrored), stencil::signedVolume(sphere), 1e-5);
    for (const glm::vec3& n : mirrored.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    expectNormalsMatchWinding(mirrored);
    // A sphere's outward normal is its position direction, mirrored or not.
    for (std::size_t i = 0; i < mirrored.positions.size(); ++i) {
      EXPECT_GT(glm::dot(mirrored.normals[i], mirrored.positions[i]), 0.99f);
    }
  }
}

TEST(Transformed, NonUniformScaleUsesInverseTranspose) {
  // Ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1: the gradient (x/a^2, y/b^2, z/c^2)
  // is the true normal. Transforming normals by the matrix itself would be wrong.
  const glm::vec3 axes(4.0f, 1.0f, 0.5f);
  const Mesh ellipsoid =
      stencil::transformed(stencil::makeSphere(1.0f, 24, 12), glm::scale(glm::mat4(1.0f), axes));
  for (std::size_t i = 0; i < ellipsoid.positions.size(); ++i) {
    const glm::vec3 expected = glm::normalize(ellipsoid.positions[i] / (axes * axes));
    EXPECT_NEAR(glm::length(ellipsoid.normals[i]), 1.0f, 1e-5f);
    EXPECT_GT(glm::dot(ellipsoid.normals[i], expected), 1.0f - 1e-5f) << "vertex " << i;
  }
  expectNormalsMatchWinding(ellipsoid);
}

TEST(Transformed, RotationKeepsVolumeAndUnitNormals) {
  const Mesh torus = stencil::makeTorus(2.0f, 0.5f, 24, 12);
  const glm::mat4 r = glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1, 2, 3)));
  const Mesh rotated = stencil::transformed(torus, r);
  EXPECT_NEAR(stencil::signedVolume(rotated), stencil::signedVolume(torus), 1e-4);
  for (const glm::vec3& n : rotated.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
  expectNormalsMatchWinding(rotated);
}

TEST(Transformed, RejectsProjectiveAndSingularMatrices) {
  const Mesh cube = stencil::makeCube(1.0f);
  EXPECT_THROW(stencil::transformed(cube, glm::perspective(1.0f, 1.0f, 0.1f, 10.0f)), std::invalid_argument);
  EXPECT_THROW(stencil::transformed(cube, glm::scale(glm::mat4(1.0f), {1, 0, 1})), std::invalid_argument);
}

}  // namespace
