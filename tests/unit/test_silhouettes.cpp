// The prepared silhouette passes (SilhouetteCaster) against the Mesh overloads of facesLight and
// possibleSilhouetteEdges: the same flags and the same edges, in the same order and direction, on every
// mesh the tests use and from lights in general position, on the mesh, in a face's plane, far
// away and directional.
#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <string>
#include <vector>

#include "geometry/adjacency.h"
#include "geometry/dual_silhouette.h"
#include "geometry/scene.h"
#include "geometry/shadow_volume.h"
#include "geometry/shapes.h"
#include "geometry/weld.h"

namespace {

using namespace stencil;

struct NamedCaster {
  std::string name;
  Mesh mesh;
  EdgeAdjacency adjacency;
};

NamedCaster named(std::string name, Mesh mesh) {
  EdgeAdjacency adjacency = buildEdgeAdjacency(mesh.indices, mesh.positions.size());
  return {std::move(name), std::move(mesh), std::move(adjacency)};
}

// Every shape, welded (closed where the shape is) and as built (split at creases: border edges),
// and every caster of every scene file the scene tests read, as the lessons prepare it.
std::vector<NamedCaster> suiteMeshes() {
  std::vector<NamedCaster> out;
  const std::pair<const char*, Mesh> shapes[] = {{"plane", makePlane(1.0f, 3)},
                                                 {"square ring", makeSquareRing(1.0f, 0.5f)},
                                                 {"screen quad", makeScreenQuad()},
                                                 {"cube", makeCube(1.0f)},
                                                 {"sphere", makeSphere(1.0f, 24, 13)},
                                                 {"torus", makeTorus(1.0f, 0.3f, 32, 16)},
                                                 {"cylinder", makeCylinder(0.5f, 2.0f, 17)},
                                                 {"cone", makeCone(0.5f, 1.0f, 9)},
                                                 {"stairs", makeStairs(6, 1.0f, 0.2f, 0.3f)}};
  for (const auto& [name, mesh] : shapes) {
    out.push_back(named(std::string(name) + " as built", mesh));
    out.push_back(named(std::string(name) + " welded", weldByPosition(mesh).mesh));
  }
  const std::filesystem::path scenes = SCENES_DIR;
  for (const auto& folder : {scenes, scenes / "hard"})
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
      if (entry.path().extension() != ".scene") continue;
      const Scene scene =
          loadScene(entry.path(), true);  // the dusk scene too: its casters are what count here
      for (const SceneObject& o : scene.objects)
        if (o.casts)
          out.push_back({entry.path().filename().string() + " " + o.name, o.caster.mesh, o.caster.adjacency});
    }
  // Meshes the scene reader refuses as casters still have edges: non-manifold, degenerate.
  for (const auto& entry : std::filesystem::directory_iterator(scenes / "meshes")) {
    const ObjMesh obj = parseObj(readObjFile(entry.path()), entry.path().filename().string());
    out.push_back(named(entry.path().filename().string() + " as read", obj.shared));
  }
  return out;
}

// Lights in general position, far, directional (w = 0, both signs), on a vertex of the mesh, and
// in the plane of a face (at a corner pushed along one of its edges): edge-on, where the strict
// test matters.
std::vector<glm::vec4> lightsFor(const Mesh& mesh) {
  std::vector<glm::vec4> lights = {{3, 4, 5, 1}, {-2.5f, 0.3f, 0.7f, 1},  {0, 0, 0, 1},  {1e4f, -3e3f, 2, 1},
                                   {0, 1, 0, 0}, {0.3f, -0.8f, 0.52f, 0}, {-1, 0, 0, 0}, {2, 4, 6, 2}};
  const std::size_t faces = mesh.triangleCount();
  for (std::size_t t = 0; t < faces; t += 1 + faces / 7) {
    const glm::vec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]];
    lights.push_back(glm::vec4(a, 1.0f));
    lights.push_back(glm::vec4(a + 3.0f * (b - a), 1.0f));
    lights.push_back(glm::vec4(b - a, 0.0f));  // a direction within the face's plane
  }
  return lights;
}

TEST(SilhouetteCaster, SameFlagsAndEdgesAsTheMeshVersionOnEveryMesh) {
  const std::vector<NamedCaster> meshes = suiteMeshes();
  ASSERT_GT(meshes.size(), 40u);
  std::size_t compared = 0, edgeOn = 0, borders = 0;
  std::vector<std::uint8_t> lit;
  std::vector<SilhouetteEdge> edges;
  for (const NamedCaster& m : meshes) {
    const SilhouetteCaster caster = prepareSilhouettes(m.mesh, m.adjacency);
    ASSERT_EQ(caster.faceCount(), m.mesh.triangleCount()) << m.name;
    borders += m.adjacency.report.borderEdges;
    for (const glm::vec4& light : lightsFor(m.mesh)) {
      const std::vector<bool> expectedLit = facesLight(m.mesh, light);
      const std::vector<SilhouetteEdge> expected = possibleSilhouetteEdges(m.adjacency, expectedLit);
      facesLight(caster, light, lit);
      ASSERT_EQ(lit.size(), expectedLit.size() + 1) << m.name;
      for (std::size_t t = 0; t < expectedLit.size(); ++t)
        ASSERT_EQ(lit[t] == 1, expectedLit[t]) << m.name << ": face " << t;
      possibleSilhouetteEdges(caster, lit, edges);
      ASSERT_EQ(edges.size(), expected.size()) << m.name;
      for (std::size_t i = 0; i < edges.size(); ++i) {
        ASSERT_EQ(edges[i].v0, expected[i].v0) << m.name << ": edge " << i;
        ASSERT_EQ(edges[i].v1, expected[i].v1) << m.name << ": edge " << i;
      }
      const std::vector<SilhouetteEdge> once = possibleSilhouetteEdges(caster, light);
      ASSERT_EQ(once.size(), expected.size()) << m.name;
      ++compared;
      // Count the cases that make the comparison worth it: some face edge-on to the light.
      for (std::size_t t = 0; t < expectedLit.size(); ++t) {
        const glm::vec3 a = m.mesh.positions[m.mesh.indices[3 * t]],
                        b = m.mesh.positions[m.mesh.indices[3 * t + 1]],
                        c = m.mesh.positions[m.mesh.indices[3 * t + 2]];
        if (glm::dot(glm::cross(b - a, c - a), glm::vec3(light) - light.w * a) == 0.0f &&
            glm::cross(b - a, c - a) != glm::vec3(0.0f)) {
          ++edgeOn;
          break;
        }
      }
    }
  }
  EXPECT_GT(compared, 1000u);
  EXPECT_GT(edgeOn, 100u);  // lights exactly in a face's plane were among them
  EXPECT_GT(borders, 0u);   // and open meshes
}

// Wallner's dual space: the same edges, in the same order and direction, as the brute force on
// every mesh and light above (lights in a face's plane, directional ones, open meshes' borders).
TEST(DualSilhouettes, SameEdgesAsTheBruteForceOnEveryMesh) {
  std::size_t compared = 0;
  std::vector<SilhouetteEdge> edges;
  for (const NamedCaster& m : suiteMeshes()) {
    const SilhouetteCaster caster = prepareSilhouettes(m.mesh, m.adjacency);
    for (std::size_t leaf : {std::size_t{1}, std::size_t{16}}) {
      const DualSilhouettes dual(caster, leaf);
      for (const glm::vec4& light : lightsFor(m.mesh)) {
        const std::vector<SilhouetteEdge> expected = possibleSilhouetteEdges(caster, light);
        dual.query(light, edges);
        ASSERT_EQ(edges.size(), expected.size()) << m.name << " leaf " << leaf;
        for (std::size_t i = 0; i < edges.size(); ++i) {
          ASSERT_EQ(edges[i].v0, expected[i].v0) << m.name << ": edge " << i;
          ASSERT_EQ(edges[i].v1, expected[i].v1) << m.name << ": edge " << i;
        }
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 2000u);
}

// On a fine sphere the query prunes: it visits under a quarter of the cells and tests under a fifth of
// the edges, and still finds exactly the brute force's, from near and far, point and directional.
TEST(DualSilhouettes, PrunesMostOfTheTreeOnAFineSphere) {
  const Mesh sphere = weldByPosition(makeSphere(1.0f, 256, 129)).mesh;
  const EdgeAdjacency adjacency = buildEdgeAdjacency(sphere.indices, sphere.positions.size());
  const SilhouetteCaster caster = prepareSilhouettes(sphere, adjacency);
  const DualSilhouettes dual(caster);
  std::vector<SilhouetteEdge> edges;
  for (const glm::vec4& light : {glm::vec4(3, 4, 5, 1), glm::vec4(1.2f, 0.1f, 0, 1), glm::vec4(0, 1, 0, 0),
                                 glm::vec4(0.3f, -0.2f, 0.9f, 0), glm::vec4(300, -200, 100, 1)}) {
    dual.query(light, edges);
    const std::vector<SilhouetteEdge> expected = possibleSilhouetteEdges(caster, light);
    ASSERT_EQ(edges.size(), expected.size());
    for (std::size_t i = 0; i < edges.size(); ++i) ASSERT_EQ(edges[i].v0, expected[i].v0);
    EXPECT_LT(dual.lastQuery().edgesTested, caster.edgeFaces.size() / 5);  // 7-13% measured
    EXPECT_LT(dual.lastQuery().cellsVisited, dual.cellCount() / 4);
  }
}

// The query reruns only when the light moves relative to the caster: the same light in the
// caster's object space (even after both moved together) reuses the last answer without a descent,
// and a light that moved, or a caster that moved under a still light, descends again. The answer
// reused is the tree's own, whatever the caller did to its vector in between.
TEST(DualSilhouettes, QueriesAgainOnlyWhenTheLightMovesRelativeToTheCaster) {
  const Mesh torus = weldByPosition(makeTorus(1.0f, 0.3f, 32, 16)).mesh;
  const EdgeAdjacency adjacency = buildEdgeAdjacency(torus.indices, torus.positions.size());
  const SilhouetteCaster caster = prepareSilhouettes(torus, adjacency);
  const DualSilhouettes dual(caster);
  const auto same = [&](const std::vector<SilhouetteEdge>& edges, const glm::vec4& light) {
    const std::vector<SilhouetteEdge> expected = possibleSilhouetteEdges(caster, light);
    if (edges.size() != expected.size() || expected.empty()) return false;
    for (std::size_t i = 0; i < edges.size(); ++i)
      if (edges[i].v0 != expected[i].v0 || edges[i].v1 != expected[i].v1) return false;
    return true;
  };
  // Light and caster in the world; the query takes the light in the caster's object space.
  const glm::vec4 world(3.0f, 4.0f, 5.0f, 1.0f);
  const auto local = [](const glm::mat4& model, const glm::vec4& light) {
    return glm::inverse(model) * light;
  };
  std::vector<SilhouetteEdge> edges;
  dual.query(local(glm::mat4(1.0f), world), edges);
  EXPECT_EQ(dual.queriesRun(), 1u);
  EXPECT_FALSE(dual.lastQuery().reused);
  EXPECT_GT(dual.lastQuery().cellsVisited, 0u);
  EXPECT_TRUE(same(edges, world));

  edges.assign(3, SilhouetteEdge{7, 7});  // another caster's edges in the same vector
  dual.query(local(glm::mat4(1.0f), world), edges);
  EXPECT_EQ(dual.queriesRun(), 1u);
  EXPECT_EQ(dual.queriesReused(), 1u);
  EXPECT_TRUE(dual.lastQuery().reused);
  EXPECT_EQ(dual.lastQuery().cellsVisited, 0u);
  EXPECT_TRUE(same(edges, world));

  // Both moved by the same translation (exact in float): the same light in object space.
  const glm::mat4 moved = glm::translate(glm::mat4(1.0f), glm::vec3(2.0f, -1.0f, 0.5f));
  const glm::vec4 movedLight = moved * world;
  ASSERT_EQ(local(moved, movedLight), world);
  dual.query(local(moved, movedLight), edges);
  EXPECT_EQ(dual.queriesRun(), 1u);
  EXPECT_TRUE(same(edges, world));

  // The caster moved under the still light: a new query, the right edges.
  dual.query(local(moved, world), edges);
  EXPECT_EQ(dual.queriesRun(), 2u);
  EXPECT_TRUE(same(edges, local(moved, world)));

  // The light moved a little; then back to the first light (only the last answer is kept).
  const glm::vec4 nudged(3.0f, 4.0f, 5.001f, 1.0f);
  dual.query(nudged, edges);
  EXPECT_EQ(dual.queriesRun(), 3u);
  EXPECT_TRUE(same(edges, nudged));
  dual.query(world, edges);
  EXPECT_EQ(dual.queriesRun(), 4u);
  EXPECT_TRUE(same(edges, world));

  // The same direction as a directional light is another light.
  dual.query(glm::vec4(3.0f, 4.0f, 5.0f, 0.0f), edges);
  EXPECT_EQ(dual.queriesRun(), 5u);
  EXPECT_TRUE(same(edges, glm::vec4(3.0f, 4.0f, 5.0f, 0.0f)));
  EXPECT_EQ(dual.queriesReused(), 2u);
  // descend() always descends, and its answer is the one reused next.
  dual.descend(glm::vec4(3.0f, 4.0f, 5.0f, 0.0f), edges);
  EXPECT_EQ(dual.queriesRun(), 6u);
  dual.query(glm::vec4(3.0f, 4.0f, 5.0f, 0.0f), edges);
  EXPECT_EQ(dual.queriesRun(), 6u);
  EXPECT_EQ(dual.queriesReused(), 3u);
}

// The hierarchy over the dual edges: the brute force's edges, order and direction included, on
// every mesh and light above, for leaves of one edge, the default and the most a leaf holds,
// through query() and through fresh descents. Lights in a face's plane reach the brute force's
// own test (the unit planes cannot decide a face within the margin of edge-on).
TEST(DualEdgeBvh, SameEdgesAsTheBruteForceOnEveryMesh) {
  std::size_t compared = 0, exact = 0;
  std::vector<SilhouetteEdge> edges;
  for (const NamedCaster& m : suiteMeshes()) {
    const SilhouetteCaster caster = prepareSilhouettes(m.mesh, m.adjacency);
    for (std::size_t leaf : {std::size_t{1}, std::size_t{8}, std::size_t{255}}) {
      const DualEdgeBvh bvh(caster, leaf);
      for (const glm::vec4& light : lightsFor(m.mesh)) {
        const std::vector<SilhouetteEdge> expected = possibleSilhouetteEdges(caster, light);
        for (bool fresh : {false, true}) {
          fresh ? bvh.descend(light, edges) : bvh.query(light, edges);
          ASSERT_EQ(edges.size(), expected.size()) << m.name << " leaf " << leaf;
          for (std::size_t i = 0; i < edges.size(); ++i) {
            ASSERT_EQ(edges[i].v0, expected[i].v0) << m.name << ": edge " << i;
            ASSERT_EQ(edges[i].v1, expected[i].v1) << m.name << ": edge " << i;
          }
        }
        exact += bvh.lastQuery().exactTests;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 3000u);
  EXPECT_GT(exact, 0u);
}

// Lights a hair off a face's plane, on both sides, where the brute force's float test and the
// unit plane's P.L could disagree without the margin: 1e-3 down to 1e-8 of the face's size off
// its plane (float resolves about 6e-8 of the light's coordinates), at a corner and beyond it,
// on a fine sphere and torus. Both dual-space structures give the brute force's edges for each.
TEST(DualEdgeBvh, SameEdgesAsTheBruteForceForLightsAHairOffAFacesPlane) {
  std::size_t compared = 0, exact = 0;
  std::vector<SilhouetteEdge> edges;
  for (const Mesh& shape : {makeSphere(1.0f, 96, 49), makeTorus(1.0f, 0.3f, 96, 48)}) {
    const Mesh mesh = weldByPosition(shape).mesh;
    const EdgeAdjacency adjacency = buildEdgeAdjacency(mesh.indices, mesh.positions.size());
    const SilhouetteCaster caster = prepareSilhouettes(mesh, adjacency);
    const DualEdgeBvh bvh(caster);
    const DualSilhouettes hextree(caster);
    for (std::size_t t = 0; t < mesh.triangleCount(); t += 97) {
      const glm::vec3 a(caster.ax[t], caster.ay[t], caster.az[t]), n(caster.nx[t], caster.ny[t], caster.nz[t]);
      const glm::vec3 b = mesh.positions[mesh.indices[3 * t + 1]];
      const float size = glm::length(b - a);
      for (float along : {0.0f, 3.0f})
        for (float off : {1e-3f, 1e-5f, 1e-6f, 1e-7f, 1e-8f, -1e-8f, -1e-7f, -1e-6f, -1e-5f, -1e-3f}) {
          const glm::vec4 light(a + along * (b - a) + off * size * glm::normalize(n), 1.0f);
          const std::vector<SilhouetteEdge> expected = possibleSilhouetteEdges(caster, light);
          for (int which = 0; which < 2; ++which) {
            which == 0 ? bvh.descend(light, edges) : hextree.descend(light, edges);
            ASSERT_EQ(edges.size(), expected.size()) << "face " << t << " off " << off << " structure " << which;
            for (std::size_t i = 0; i < edges.size(); ++i) {
              ASSERT_EQ(edges[i].v0, expected[i].v0) << "face " << t << " off " << off;
              ASSERT_EQ(edges[i].v1, expected[i].v1) << "face " << t << " off " << off;
            }
          }
          exact += bvh.lastQuery().exactTests;
          ++compared;
        }
    }
  }
  EXPECT_GT(compared, 1000u);
  EXPECT_GT(exact, compared);  // the closest lights leave faces to the brute force's test
}

// Output-sensitive: on a fine sphere (98k edges, a silhouette of about 400) the hierarchy tests
// under 5% of the edges (1.0-2.2% measured) and visits under a tenth of its nodes (3-6.5%), where
// Wallner's hextree tests 7-13% of the edges; fewer edges than the hextree for every light.
TEST(DualEdgeBvh, TestsFewerEdgesThanTheHextreeOnAFineSphere) {
  const Mesh sphere = weldByPosition(makeSphere(1.0f, 256, 129)).mesh;
  const EdgeAdjacency adjacency = buildEdgeAdjacency(sphere.indices, sphere.positions.size());
  const SilhouetteCaster caster = prepareSilhouettes(sphere, adjacency);
  const DualEdgeBvh bvh(caster);
  const DualSilhouettes hextree(caster);
  std::vector<SilhouetteEdge> edges;
  for (const glm::vec4& light : {glm::vec4(3, 4, 5, 1), glm::vec4(1.2f, 0.1f, 0, 1), glm::vec4(0, 1, 0, 0),
                                 glm::vec4(0.3f, -0.2f, 0.9f, 0), glm::vec4(300, -200, 100, 1)}) {
    bvh.query(light, edges);
    const std::vector<SilhouetteEdge> expected = possibleSilhouetteEdges(caster, light);
    ASSERT_EQ(edges.size(), expected.size());
    for (std::size_t i = 0; i < edges.size(); ++i) ASSERT_EQ(edges[i].v0, expected[i].v0);
    EXPECT_LT(bvh.lastQuery().edgesTested, caster.edgeFaces.size() / 20);
    EXPECT_LT(bvh.lastQuery().nodesVisited, bvh.nodeCount() / 10);
    hextree.query(light, edges);
    EXPECT_LT(bvh.lastQuery().edgesTested, hextree.lastQuery().edgesTested);
  }
}

// The same cache as DualSilhouettes: a light equal bit for bit reuses the last answer.
TEST(DualEdgeBvh, QueriesAgainOnlyWhenTheLightChanges) {
  const Mesh torus = weldByPosition(makeTorus(1.0f, 0.3f, 32, 16)).mesh;
  const EdgeAdjacency adjacency = buildEdgeAdjacency(torus.indices, torus.positions.size());
  const SilhouetteCaster caster = prepareSilhouettes(torus, adjacency);
  const DualEdgeBvh bvh(caster);
  const glm::vec4 light(3.0f, 4.0f, 5.0f, 1.0f);
  const std::vector<SilhouetteEdge> expected = possibleSilhouetteEdges(caster, light);
  std::vector<SilhouetteEdge> edges;
  bvh.query(light, edges);
  EXPECT_EQ(bvh.queriesRun(), 1u);
  EXPECT_GT(bvh.lastQuery().nodesVisited, 0u);
  edges.assign(3, SilhouetteEdge{7, 7});
  bvh.query(light, edges);
  EXPECT_EQ(bvh.queriesRun(), 1u);
  EXPECT_EQ(bvh.queriesReused(), 1u);
  EXPECT_TRUE(bvh.lastQuery().reused);
  EXPECT_EQ(bvh.lastQuery().nodesVisited, 0u);
  ASSERT_EQ(edges.size(), expected.size());
  for (std::size_t i = 0; i < edges.size(); ++i) EXPECT_EQ(edges[i].v0, expected[i].v0);
  bvh.query(glm::vec4(3.0f, 4.0f, 5.001f, 1.0f), edges);
  EXPECT_EQ(bvh.queriesRun(), 2u);
  bvh.descend(glm::vec4(3.0f, 4.0f, 5.001f, 1.0f), edges);
  EXPECT_EQ(bvh.queriesRun(), 3u);
}

// A light with an infinite or NaN coordinate prunes and decides nothing: every edge goes to the
// brute force's test, whose answer both structures return.
TEST(DualEdgeBvh, InfiniteAndNaNLightsGiveTheBruteForcesEdges) {
  const Mesh sphere = weldByPosition(makeSphere(1.0f, 24, 13)).mesh;
  const EdgeAdjacency adjacency = buildEdgeAdjacency(sphere.indices, sphere.positions.size());
  const SilhouetteCaster caster = prepareSilhouettes(sphere, adjacency);
  const DualEdgeBvh bvh(caster);
  const DualSilhouettes hextree(caster);
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<SilhouetteEdge> edges;
  for (const glm::vec4& light : {glm::vec4(inf, 0, 0, 1), glm::vec4(3, nan, 5, 1), glm::vec4(0, 0, -inf, 0)}) {
    const std::vector<SilhouetteEdge> expected = possibleSilhouetteEdges(caster, light);
    for (int which = 0; which < 2; ++which) {
      which == 0 ? bvh.query(light, edges) : hextree.query(light, edges);
      ASSERT_EQ(edges.size(), expected.size()) << which;
      for (std::size_t i = 0; i < edges.size(); ++i) {
        EXPECT_EQ(edges[i].v0, expected[i].v0);
        EXPECT_EQ(edges[i].v1, expected[i].v1);
      }
    }
    EXPECT_EQ(bvh.lastQuery().edgesTested, caster.edgeFaces.size());
  }
}

TEST(SilhouetteCaster, RefusesFlagsOfTheWrongSizeAndAdjacencyOfAnotherMesh) {
  const Mesh cube = weldByPosition(makeCube(1.0f)).mesh;
  const EdgeAdjacency adjacency = buildEdgeAdjacency(cube.indices, cube.positions.size());
  const SilhouetteCaster caster = prepareSilhouettes(cube, adjacency);
  std::vector<std::uint8_t> lit(caster.faceCount(), 0);  // no border flag
  std::vector<SilhouetteEdge> edges;
  EXPECT_THROW(possibleSilhouetteEdges(caster, lit, edges), std::invalid_argument);
  Mesh fewer = cube;
  fewer.indices.resize(6);
  EXPECT_THROW(prepareSilhouettes(fewer, adjacency), std::invalid_argument);
}

}  // namespace
