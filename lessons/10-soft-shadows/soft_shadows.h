// Lesson 10's parts: the scene's measures, the stencil bits, and the lesson itself. main.cpp
// defines the algorithms, in the papers' order (Kilgard's eight bits, the corrected count, the
// penumbra wedges); reference.cpp the exact answers the pictures are judged by (the analytic
// visible fraction, the converged ray cast, the penumbra's width measured); convex_hull.cpp the
// hull each wedge is drawn as; classroom.cpp what surrounds them (the options, variants and
// camera, the scene, the targets and the drawing the passes share, the oracle's claim), none of
// which changes how a shadow is counted.
#pragma once
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geometry/mesh.h"
#include "geometry/shadow_volume.h"
#include "geometry/soft_shadow.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/shader.h"

namespace stencil::soft_shadows {

constexpr int kMaxLights = 1024;

// ---- the scene: an area light over a slab over the ground -----------------------------------

constexpr float kLightHeight = 4.0f;  // H
constexpr float kSlabHeight = 1.2f;   // h, the slab's mid-plane
constexpr float kSlabThickness = 0.02f;
constexpr float kSlabSide = 1.2f;
constexpr glm::vec3 kSlabCentre{-0.15f, kSlabHeight, 0.1f};
constexpr glm::vec3 kBallCentre{0.35f, 2.3f, 0.45f};
constexpr float kBallRadius = 0.3f;
constexpr float kGroundHalf = 3.0f;
constexpr int kGroundDivisions = 12;
constexpr glm::vec3 kAmbient{0.18f};
constexpr glm::vec3 kLightColour{1.7f, 1.6f, 1.4f};

// Stencil bits with the wedges: the count in the low four (two convex casters count to 2,
// wrapping modulo 16 on the way), a wedge's z-fail parity, the wedges' union, the added bit.
constexpr GLuint kCountBits = 0x0F, kTempBit = 0x20, kWedgeBit = 0x40, kAddedBit = 0x80;
constexpr float kWedgeFloor = -0.5f;  // wedges end below every receiver (the ground is y = 0)

struct Object {
  const Mesh* mesh;
  const GpuMesh* gpu;
  glm::mat4 model;
  glm::vec3 colour;
  bool caster;
};

// A colour texture (RGBA16F, RGBA8 or RGBA32F) with, optionally, a packed depth/stencil buffer of
// the framework's format, so depth and stencil blit to it unchanged. size in pixels; throws
// std::runtime_error where GL calls it incomplete.
class Target {
 public:
  Target(glm::ivec2 size, GLenum colourFormat, bool depthStencil);
  ~Target();
  Target(const Target&) = delete;
  Target& operator=(const Target&) = delete;

  bool fits(glm::ivec2 size, GLenum format) const { return size == size_ && format == format_; }
  void bind() const;  // for drawing, the viewport its whole size
  GLuint fbo() const { return fbo_; }
  GLuint colour() const { return colour_; }

 private:
  glm::ivec2 size_;
  GLenum format_;
  GLuint fbo_ = 0, colour_ = 0, depthStencil_ = 0;
};

class SoftShadows final : public Lesson {
 public:
  SoftShadows();
  ~SoftShadows() override;
  SoftShadows(const SoftShadows&) = delete;
  SoftShadows& operator=(const SoftShadows&) = delete;

  void render(Frame& f) override;

  // The checked light's stencil against a ray cast from that light: counting keeps its count
  // (0 lit), Kilgard its bit. In classroom.cpp.
  std::optional<ShadowCheck> shadowCheck(const Frame& f) const override;

 private:
  // Each defined with its comment.
  // ---- main.cpp: the algorithms ------------------------------------------------------------------
  void kilgardLights(Frame& f, const std::vector<Object>& scene);
  void countingLights(Frame& f, const std::vector<Object>& scene);
  void countVolumes(Frame& f, const glm::vec4& light, bool inWedges);
  void wedgeLights(Frame& f, const std::vector<Object>& scene, const AreaLight& area);
  void illuminate(Frame& f, const std::vector<Object>& scene, const glm::vec4& light, bool allLights = false);
  void volumeState(const Frame& f);
  static void restoreState();

  // ---- reference.cpp: the exact answers ----------------------------------------------------------
  void drawReference(Frame& f, const AreaLight& area, const glm::mat4& viewProjection);
  void drawConverged(Frame& f, const std::vector<Object>& scene, const AreaLight& area,
                     const glm::mat4& viewProjection);
  static void measurePenumbra(Frame& f, const Target& picture, const AreaLight& area);

  // ---- classroom.cpp: the scene, the passes' snapshots, the drawing they share -------------------
  static void checkOptions(const Frame& f);
  static void startCounts(Frame& f);
  std::vector<Object> sceneOf(const Frame& f) const;
  std::vector<const PreparedCaster*> casters(const Frame& f) const;
  static float share(const Frame& f);
  void endPass(Frame& f, const char* name);
  void saveStencil();
  void drawVolume(Frame& f, const ShadowVolume& v);
  void drawScene(const Frame& f, const std::vector<Object>& scene, glm::vec4 light, glm::vec3 colour,
                 glm::vec3 ambient, bool visibility, bool allLights = false);
  void drawPicture(const Target& from, int lights, bool tint);
  void tintWedges();

  Program light_, flat_, volume_, resolve_, lights_;
  GLuint lightsTexture_ = 0;
  Mesh groundMesh_, matMesh_, slabMesh_, ballMesh_;
  GpuMesh ground_, mat_, slab_, ball_;
  PreparedCaster slabEdges_, ballEdges_;  // welded, in world space (the scene stands still)
  GpuTriangles volumeStream_;
  WindowRectangle window_;
  std::unique_ptr<Target> target_, saved_, average_;
  GLuint framework_ = 0;
  glm::ivec2 size_{0};
  std::vector<glm::vec4> samples_;  // this round's point lights
  int checked_ = 0;
  int round_ = 0;
  std::string lastKey_;
};

// ---- main.cpp ------------------------------------------------------------------------------------

// Every wedge of a caster (welded, world space) for the light's bounding rectangle grown by
// `scale`: appends the triangles (w = 1) and each wedge's (first vertex, vertex count).
void penumbraWedges(const PreparedCaster& caster, const AreaLight& area, float scale,
                    std::vector<glm::vec4>& out, std::vector<std::pair<GLint, GLsizei>>& ranges);

// ---- convex_hull.cpp -----------------------------------------------------------------------------

// The convex hull of a few points (a dozen) as triangles counter-clockwise seen from outside, w = 1;
// empty when the points span no volume.
std::vector<glm::vec4> convexHullTriangles(const std::vector<glm::dvec3>& points);

// ---- classroom.cpp -------------------------------------------------------------------------------

// The lesson's name, options, variants and camera.
LessonInfo lessonInfo();

// The area light the options ask for: `size` tenths wide, two thirds as deep, at height H.
AreaLight areaLight(const Frame& f);
glm::mat4 slabModel();  // the unit cube onto the slab
// The ground's triangles under the mat, the same vertices (equal depths).
Mesh matFrom(const Mesh& ground);

// Copies what `mask` names from one framebuffer to another of the same size.
void blit(GLuint from, GLuint to, glm::ivec2 size, GLbitfield mask);

}  // namespace stencil::soft_shadows
