// Scenes from a text file: the objects (procedural primitives or OBJ meshes), their transforms
// and motion, the lights with their type, colour and bounds, and the camera. Lessons 15 and 16
// render any scene described this way (--scene FILE), so a user can try the shadow-volume
// system on a model of their own, and each hard case is a small file.
//
// Casters are prepared for shadow volumes when the scene is read (shadow_volume.h's
// prepareCaster): seams
// welded, degenerate triangles dropped, and what the mesh breaks of the requirements (closed,
// two-manifold, consistently wound) reported in words.
#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <glm/glm.hpp>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/adjacency.h"
#include "geometry/mesh.h"
#include "geometry/shadow_oracle.h"
#include "geometry/shadow_volume.h"
#include "geometry/solar.h"

namespace stencil {

// A bad scene file: the message starts with "FILE:LINE: " ("FILE: " for what is wrong with the
// whole file). One printable line: the constructor writes any other byte as \xNN.
struct SceneError : std::runtime_error {
  explicit SceneError(const std::string& message);
};

// What a scene file may ask for (docs/scenes.md). The lessons are for teaching: a file beyond
// these is refused at the line that crosses them, rather than run for minutes without a word.
inline constexpr std::size_t kMaxSceneLights = 16;
inline constexpr std::size_t kMaxSceneObjects = 1024;
inline constexpr std::size_t kMaxSceneTriangles = 1'000'000;  // all objects together
inline constexpr std::uintmax_t kMaxSceneFileBytes = 1u << 20;
inline constexpr std::uintmax_t kMaxObjFileBytes = 64u << 20;
inline constexpr std::size_t kMaxObjFaceCorners = 256;     // corners of one OBJ face
inline constexpr float kMaxObjCoordinate = 1e6f;           // |x|, |y|, |z| of an OBJ vertex
inline constexpr std::size_t kMaxSceneCsgProducts = 4096;  // the csg expression's sum of products
// Where a scene may put things and how much it may scale them: |x|, |y|, |z| of the camera, a
// point light and every point of every object (at every time, spin and bob included) within
// kMaxSceneCoordinate; a shape's sizes and a model matrix's stretch (its singular values) within
// kMinSceneScale..kMaxSceneCoordinate. A float still resolves a millionth of the largest size,
// and the matrices, normals and ray casts built from them stay finite and invertible.
inline constexpr float kMaxSceneCoordinate = 1e6f;
inline constexpr float kMinSceneScale = 1e-6f;
// The times a lesson may render a scene at, |t| in seconds (--time's bound, gl/options.h's kMaxTime).
inline constexpr double kMaxSceneTime = 1e6;

// A sun light's place and clock (`light sun` in a scene file): its position is the direction
// towards the sun then (solar.h; world +y up, -z north, +x east), at w = 0.
struct SunLight {
  SitePlace place;
  CivilTime time;
};

struct SceneLight {
  glm::vec4 position{0.0f, 5.0f, 0.0f, 1.0f};  // w = 1 a point (world), w = 0 the direction towards the light
  glm::vec3 colour{1.0f};
  // A point light's bounds: its light falls to zero at this distance (attenuation), so nothing
  // outside the sphere needs its shadow. Infinite for a light without bounds.
  float radius = std::numeric_limits<float>::infinity();
  std::optional<SunLight> sun{};  // set for a sun light, which is directional
};

struct SceneObject {
  std::string name;
  int line = 0;  // its object line in the scene file; 0 when built in code
  Mesh mesh;     // object space, with normals, as drawn
  glm::mat4 model{1.0f};
  glm::vec3 colour{0.8f};
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
SceneObject sceneObject(std::string name, Mesh mesh, const glm::mat4& model, const glm::vec3& colour,
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
  // A CSG expression over the objects (the `csg` line; geometry/csg.h's text form, the objects'
  // names its primitives): lesson 14 renders it. Empty when the file has none. Every object it
  // names is closed (checked when the scene is read).
  std::string csg;
  int csgLine = 0;  // its line in the scene file
  SceneCamera camera;
  glm::vec3 ambient{0.1f};
  std::vector<SceneLight> lights;
  std::vector<SceneObject> objects;
};

// Rooms and buried lights (geometry/solid.h) for one frame: which closed casters hold the eye,
// and why lessons 15 and 16 cannot draw the scene, if they cannot (one line naming the object;
// empty when they can): the eye or a point light on a caster's surface (neither inside nor
// outside it), a caster whose faces point in seen from outside (a solid written inside out), or
// a room that is not convex (its walls would shadow parts of its own inside, and the volume of a
// solid that reaches to infinity is not one z-fail can count).
struct SolidsSeen {
  std::vector<bool> room;  // per object
  std::string refusal;
};
SolidsSeen solidsSeenFrom(const Scene&, const std::vector<glm::mat4>& models, const glm::vec3& eye);

// Whether a light (world, homogeneous) is buried in a casting object's solid: it then lights
// nothing the eye sees, and its whole picture is shadow.
bool lightBuried(const Scene&, const std::vector<glm::mat4>& models, const SolidsSeen&,
                 const glm::vec4& light);

// The scene at a time as the shadow oracle sees it (geometry/shadow_oracle.h): every object's
// drawn mesh at its model matrix then, with its casts and receives. Points into the scene.
std::vector<OracleObject> oracleObjects(const Scene&, double time);

// An OBJ file's triangles (polygons triangulated, all its groups in one mesh), two ways:
// `drawn` with normals, the file's where every corner has one, else each triangle its own three
// vertices and flat normal; `shared`, positions only, each of the file's vertices once (in the
// order the faces first use them) and indexed as the file indexes them, for prepareCaster.
struct ObjMesh {
  Mesh drawn, shared;
};

// Reads OBJ text; `name` names it in messages. Every face index (position, texture coordinate,
// normal; 1-based, or negative counting back from the last one defined above) is checked
// before the text is used. Throws SceneError "NAME:LINE: what is wrong" (an index out of range
// or too large, a coordinate not finite or beyond kMaxObjCoordinate, a face of more than
// kMaxObjFaceCorners corners, more than kMaxSceneTriangles triangles), or "NAME: ..." when the
// file has no faces or tinyobjloader refuses it.
ObjMesh parseObj(std::string_view text, const std::string& name);

// The text of an OBJ file a scene names. Throws std::runtime_error with the reason in a few
// words, without the path: "no such file", "it is a directory", "it is N bytes, ...".
std::string readObjFile(const std::filesystem::path& path);

// Where parseScene gets an OBJ file's text, given its path (joined to the scene file's folder).
// readObjFile reads the disk; a test may serve text from memory. Throws std::runtime_error.
using ObjFileReader = std::function<std::string(const std::filesystem::path&)>;

// Reads a scene file (the format is documented in docs/scenes.md). OBJ paths are relative to
// the scene file. Throws SceneError ("FILE:LINE: what is wrong", or "FILE: what is wrong" when
// the file cannot be read, is not a regular file or is over kMaxSceneFileBytes) for anything it
// cannot use; a caster whose mesh is not usable for shadow volumes is an error that names the
// edges' problem. A csg line is checked against the objects: an unknown name or a syntax error
// (with its column in the line), a sum of products past kMaxSceneCsgProducts, or an object it
// names that is not a closed solid is an error at that line. Returns the scene, every caster
// prepared. A sun light below the horizon at the file's time is an error (it lights nothing),
// unless sunMayBeDown: a shadow profile (--shadow-hours) moves the sun through a span of the day
// and takes the steps at night as night; the light then points where the sun stands, below.
Scene loadScene(const std::filesystem::path& file, bool sunMayBeDown = false);
// The same for a scene's text; `file` names it in messages and locates its OBJ files, which
// `readObj` reads.
Scene parseScene(std::string_view text, const std::filesystem::path& file,
                 const ObjFileReader& readObj = readObjFile, bool sunMayBeDown = false);

}  // namespace stencil
