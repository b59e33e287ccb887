// The prepared silhouette passes (SilhouetteCaster) against the Mesh overloads of facesLight and
// possibleSilhouetteEdges: the same flags and the same edges, in the same order and direction, on every
// mesh the tests use and from lights in general position, on the mesh, in a face's plane, far
// away and directional.
#include <gtest/gtest.h>

#include <filesystem>
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
      const Scene scene = loadScene(entry.path());
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
    EXPECT_LT(dual.lastQuery().edgesTested, caster.edgeFaces.size() / 5);  // 11-14% measured
    EXPECT_LT(dual.lastQuery().cellsVisited, dual.cellCount() / 4);
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
