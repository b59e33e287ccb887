// libFuzzer target: a scene file's text through parseScene. After a line "%%obj" the rest of the
// input is the text of every OBJ file the scene names (without one, a closed tetrahedron); OBJ
// files are served from memory, so nothing outside the input is read. A SceneError is the
// expected answer to bad input; any other exception, crash or sanitizer report is a bug, and so is a
// scene read without error whose model matrices (at any time) or lights the lessons cannot use.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_check.h"
#include "geometry/scene.h"

namespace {

constexpr std::string_view tetrahedron =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
constexpr std::string_view separator = "\n%%obj\n";

// A unit tetrahedron as a mesh: a large object's model matrix is checked on it.
const stencil::Mesh& tetrahedronMesh() {
  static const stencil::Mesh mesh = [] {
    stencil::Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    m.normals = {{0, 0, -1}, {0, -1, 0}, {-1, 0, 0}, {0.577f, 0.577f, 0.577f}};
    m.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    return m;
  }();
  return mesh;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  std::string_view scene = input, obj = tetrahedron;
  if (const std::size_t at = input.find(separator); at != std::string_view::npos) {
    scene = input.substr(0, at + 1);
    obj = input.substr(at + separator.size());
  }
  try {
    const stencil::Scene s =
        stencil::parseScene(scene, "fuzz/in.scene", [&](const std::filesystem::path&) { return std::string(obj); });
    std::size_t triangles = 0;
    for (const stencil::SceneObject& o : s.objects) {
      stencil::validateMesh(o.mesh);
      if (!stencil::allFinite(o.mesh)) __builtin_trap();
      triangles += o.mesh.triangleCount();
      // What the scene becomes at any time a lesson may render it: every model matrix is one the
      // lessons and the ray casts can use (affine, invertible, its world points finite and within
      // the scene's bounds). transformed() throws where it is not.
      // (A large mesh's points are left to the smaller ones: the matrix is what is checked.)
      const stencil::Mesh& probe = o.mesh.positions.size() <= 20000 ? o.mesh : tetrahedronMesh();
      for (const double t : {0.0, 1.0, -3.7, 1234.5, stencil::kMaxSceneTime, -stencil::kMaxSceneTime}) {
        const stencil::Mesh world = stencil::transformed(probe, o.modelAt(t));
        if (!stencil::allFinite(world)) __builtin_trap();
        for (const glm::vec3& p : world.positions)
          if (glm::any(glm::greaterThan(glm::abs(p), glm::vec3(1.001f * stencil::kMaxSceneCoordinate))))
            __builtin_trap();
      }
    }
    // Every light a position or a unit direction.
    for (const stencil::SceneLight& l : s.lights) {
      for (int i = 0; i < 4; ++i)
        if (!std::isfinite(l.position[i])) __builtin_trap();
      if (l.position.w == 0.0f && std::abs(glm::length(glm::vec3(l.position)) - 1.0f) > 1e-5f) __builtin_trap();
      if (l.position.w != 0.0f &&
          glm::any(glm::greaterThan(glm::abs(glm::vec3(l.position)), glm::vec3(stencil::kMaxSceneCoordinate))))
        __builtin_trap();
    }
    if (s.lights.size() > stencil::kMaxSceneLights || s.objects.size() > stencil::kMaxSceneObjects ||
        triangles > stencil::kMaxSceneTriangles)
      __builtin_trap();
  } catch (const stencil::SceneError& e) {
    stencil::fuzz::checkMessage(e.what(), "fuzz/in.scene:");
  }
  return 0;
}
