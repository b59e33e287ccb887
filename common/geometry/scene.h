// Scenes from a text file: the objects (procedural primitives or OBJ meshes), their transforms
// and motion, the lights with their type, colour and bounds, and the camera. Lessons 15 and 16
// render any scene described this way (--scene FILE), so a user can try the shadow-volume
// system on a model of their own, and each hard case is a small file.
//
// Casters are prepared for shadow volumes when the scene is read (prepareCaster): seams
// welded, degenerate triangles dropped, and what the mesh breaks of the requirements (closed,
// two-manifold, consistently wound) reported in words.
#pragma once
#include <filesystem>
#include <glm/glm.hpp>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/adjacency.h"
#include "geometry/mesh.h"
#include "geometry/shadow_oracle.h"

namespace stencil {

// A bad scene file: the message starts with "FILE:LINE: ".
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What preparing a caster found and did. Open meshes are kept: their border edges extrude as
// silhouette edges (shadow_volume.h), and their faces cap the volume from both sides.
struct CasterReport {
  std::size_t inputVertices = 0, weldedVertices = 0;
  std::size_t droppedDegenerate = 0;  // triangles with a repeated vertex or zero area, removed
  std::size_t borderEdges = 0;        // open mesh
  std::size_t nonManifoldEdges = 0;   // three or more faces: refused
  std::size_t inconsistentEdges = 0;  // two faces walking the edge the same way: refused
  bool closed() const { return borderEdges == 0 && usable(); }
  bool usable() const { return nonManifoldEdges == 0 && inconsistentEdges == 0; }
  std::vector<std::string> messages;  // one line each, for the user
};

// A caster made fit for shadow volumes: welded positions (no normals), degenerate triangles
// dropped, and its edges' faces.
struct PreparedCaster {
  Mesh mesh;
  EdgeAdjacency adjacency;
  CasterReport report;
};
PreparedCaster prepareCaster(const Mesh& mesh);

struct SceneLight {
  glm::vec4 position{0.0f, 5.0f, 0.0f, 1.0f};  // w = 1 a point (world), w = 0 the direction towards the light
  glm::vec3 color{1.0f};
  // A point light's bounds: its light falls to zero at this distance (attenuation), so nothing
  // outside the sphere needs its shadow. Infinite for a light without bounds.
  float radius = std::numeric_limits<float>::infinity();
};

struct SceneObject {
  std::string name;
  Mesh mesh;  // object space, with normals, as drawn
  glm::mat4 model{1.0f};
  glm::vec3 color{0.8f};
  bool casts = true, receives = true;
  // Motion: at time t the model matrix is model * rotate(spinDegPerSecond * t, spinAxis) — about
  // the object's own origin — followed by a translation of bob * sin(t) along y.
  glm::vec3 spinAxis{0.0f, 1.0f, 0.0f};
  float spinDegPerSecond = 0.0f;
  float bob = 0.0f;
  glm::mat4 modelAt(double time) const;
  PreparedCaster caster;  // filled for casters when the scene is read
};

// An object for a scene built in code, its caster prepared as a file's would be.
SceneObject sceneObject(std::string name, Mesh mesh, const glm::mat4& model, const glm::vec3& color,
                        bool casts = true);

struct SceneCamera {
  glm::vec3 eye{0.0f, 3.0f, 8.0f}, target{0.0f}, up{0.0f, 1.0f, 0.0f};
  float fovyDeg = 45.0f;
  float nearPlane = 0.1f;
  float farPlane = std::numeric_limits<float>::infinity();  // the lesson decides what infinity means
  bool orthographic = false;
  float orthoHeight = 10.0f;  // the view's height in world units, when orthographic
  bool mirrored = false;      // the picture flipped left to right (a view with negative determinant)
};

struct Scene {
  std::filesystem::path file;  // where it came from; empty when built in code
  SceneCamera camera;
  glm::vec3 ambient{0.1f};
  std::vector<SceneLight> lights;
  std::vector<SceneObject> objects;
};

// The scene at a time as the shadow oracle sees it (geometry/shadow_oracle.h): every object's
// drawn mesh at its model matrix then, with its casts and receives. Points into the scene.
std::vector<OracleObject> oracleObjects(const Scene&, double time);

// Reads a scene file (the format is documented in docs/scenes.md). OBJ paths are relative to
// the scene file. Throws SceneError ("FILE:LINE: what is wrong") for anything it cannot use;
// a caster whose mesh is not usable for shadow volumes is an error that names the edges' problem.
Scene loadScene(const std::filesystem::path& file);
Scene parseScene(std::string_view text, const std::filesystem::path& file);

}  // namespace stencil
