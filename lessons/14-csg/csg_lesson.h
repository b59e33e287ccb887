// Lesson 14's parts: the scene as the lesson keeps it, and the lesson itself. main.cpp defines the
// algorithms, in the papers' order (the demo's two solids, Goldfeather, layered Goldfeather, SCS);
// drawing.cpp the work buffer, the frame's state and the draws they share; classroom.cpp what
// surrounds them (the lesson's own scenes, cameras, options, variants and --stats counts);
// refusals.cpp what no method draws right, refused in one line; oracle.cpp the check against the
// CSG ray cast. None of the last three changes what a pixel shows.
#pragma once
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include "geometry/bounds.h"
#include "geometry/csg.h"
#include "geometry/fast_shadows.h"
#include "geometry/scene.h"
#include "gl/depth_mapping.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/shader.h"

namespace stencil::csg_lesson {

// The two-solid method's operations (the "op" option), and the methods.
constexpr int kUnion = 0, kIntersection = 1, kAMinusB = 2, kBMinusA = 3;
constexpr int kTwoSolids = 0, kGoldfeather = 1, kLayered = 2, kScs = 3, kAutomatic = 4;
// The two-solid method's stencil: bit 0 the count's parity, bits 7 and 6 where A's and B's
// surfaces were kept (the primitive each pixel shows).
constexpr GLuint kParity = 0x01, kKeptA = 0x80, kKeptB = 0x40;
inline const glm::vec4 kBackground(0.1f, 0.1f, 0.13f, 1.0f);

// A CSG scene: named primitives (closed, outward-wound meshes) and an expression over them.
struct Primitive {
  std::string name;
  Mesh mesh;
  glm::mat4 model;
  glm::vec3 colour;
};
struct CsgScene {
  std::vector<Primitive> primitives;
  std::string expression;
  float spinDegPerSecond = 15.0f;  // the whole solid turns about +y
};

class Csg final : public Lesson {
 public:
  explicit Csg(const Scene* fromFile);
  ~Csg() override;
  void render(Frame& f) override;

 private:
  // Each defined with its comment.
  // The stencil's counts of target faces within a product's rectangle, read back once
  // (automatic.cpp, readCounts).
  struct LayerCounts {
    ScissorRect box;              // the rectangle read (the scissor box)
    std::vector<GLubyte> counts;  // per pixel, rows from the bottom
    int largest = 0;
    std::vector<ScissorRect> layers;  // per k, the rectangle of the pixels with a k-th fragment (count > k)
    int largestWithin(const ScissorRect& r) const;
    int at(int x, int y) const;  // x, y from the box's corner
  };
  // ---- main.cpp: the algorithms ------------------------------------------------------------------
  void keepSurface(Frame& f, int x, GLenum faces, int s, bool wantInside, GLuint kept, bool trim);
  void twoSolidsMethod(Frame& f, const CsgScene&, int op);
  void goldfeather(Frame& f, const SumOfProducts& sop, bool layered);
  bool trimLayer(Frame& f, const CsgProduct& p, const std::vector<int>& targets,
                 const std::vector<int>& trimmers, int layer, bool automatic = false);
  void mergeIntoFrame(Frame& f, const CsgProduct& p, const std::vector<int>& targets, bool fromNearest = false);
  void keepNearest(Frame& f, int layer);
  void clearNearest();
  int targetDepthComplexity(Frame& f, const CsgProduct& p, const std::vector<int>& targets,
                            LayerCounts* counts = nullptr);
  void scs(Frame& f, const SumOfProducts& sop);
  void scsEnter(Frame& f, const CsgProduct& p, bool automatic = false);
  void scsSubtract(Frame& f, const std::vector<int>& batch, bool automatic = false, GLuint query = 0,
                   bool clean = false);
  BoundingSphere worldSphereOf(int i) const;
  bool reachesPastFar(const Frame& f, int i) const;
  void clipByIntersection(Frame& f, const CsgProduct& p, bool cleared = false);

  // ---- automatic.cpp: per product the method that is right for it, with OpenCSG's economies ------
  void automatic(Frame& f, const SumOfProducts& sop);
  void scsUntilUnchanged(Frame& f, const CsgProduct& p, const ScissorRect& within);
  void layeredByLayerRects(Frame& f, const CsgProduct& p, const ScissorRect& within);
  static LayerCounts readCounts();
  std::vector<bool> primitivesIn(const ScissorRect& r) const;
  struct Footprint {
    Aabb box;
    BoundingSphere sphere;
    ScissorRect rect;
  };
  Footprint footprintOf(const Frame& f, int i) const;
  static ScissorRect common(const ScissorRect& a, const ScissorRect& b);  // their intersection
  static bool overlap(const ScissorRect& a, const ScissorRect& b);
  static bool meet(const Footprint& a, const Footprint& b);

  // ---- drawing.cpp: the work buffer and the draws ------------------------------------------------
  void workBuffer(glm::ivec2 size);
  static void makeWorkBuffer(glm::ivec2 size, GLuint& framebuffer, GLuint& depth, GLuint& colour, GLuint& primitive);
  void clearWork();
  CsgTree prepare(const CsgScene& scene, const Frame& f);
  static bool subtracted(const CsgProduct& p, int primitive);
  // Depth: white, for the depth and stencil alone; Selected: lit, the primitive written beside the
  // depth; Primitive: the primitive alone (the automatic method); Merged: lit where the frame holds
  // the fragment's primitive and depth.
  enum class Paint { Depth, Selected, Primitive, Merged };
  void drawTargets(const CsgProduct& p, const std::vector<int>& targets, Paint paint);
  void setLighting(const Program& p, const Frame& f) const;
  void drawDepth(int i);
  void drawShaded(int i);
  void drawSelected(int i);
  void drawPrimitive(int i);
  void drawMerged(int i);
  void drawWithMergeShader(int i, bool merging);  // drawSelected and drawMerged: the merge shader either way
  void mergeInputs();
  void frontFace(int i);
  void drawQuad(const glm::vec4& colour, float depth);
  void beginFrame(const Frame& f, bool clearNow);
  void clearFrame();
  void endFrame(const Frame& f);
  void abandonFrame(const Frame& f);  // endFrame from wherever a method stopped (a refusal)
  void unscissorAndDrawToBoth(const Frame& f);  // the automatic method's scissor and draw buffers undone
  static std::uint64_t samplesPassed(Frame& f, const std::function<void()>& draw);
  static void bindSurface(GLuint depth, GLuint primitive);
  void fullScreen(const Program& program);
  // Back to the far plane, the background's colour where colour is written.
  void farQuad() { drawQuad(kBackground, static_cast<float>(depth_.farthest)); }

  // ---- refusals.cpp: what no method draws right, refused -----------------------------------------
  void refuseCuts(const Frame& f, const CsgScene& scene, const SumOfProducts& sop) const;
  void refuseNear(const Frame& f) const;
  [[noreturn]] void refuseDeepCount(Frame& f, const CsgProduct& p, const std::vector<int>& targets);

  // ---- classroom.cpp: the --stats counts a method starts from ------------------------------------
  static void startCounts(Frame& f, const SumOfProducts& sop, std::initializer_list<const char*> zeros,
                          bool beforePruning = false);

  // ---- oracle.cpp: the test hook -----------------------------------------------------------------
  void checkAgainstRayCast(Frame& f, const CsgScene& scene, const CsgTree& tree, int method) const;

  const Scene* fromFile_;  // --scene's file, or nullptr for the lesson's own scenes
  Program light_, depthOnly_, merge_, select_, keep_, resolve_, flat_;
  Mesh quadMesh_;
  GpuMesh quad_;
  std::vector<std::unique_ptr<GpuMesh>> meshes_;
  std::vector<glm::vec3> colours_;
  // This frame's (prepare): the point everything is drawn from (the world's origin, or the eye far
  // from it); per primitive, its model to the world less origin_; and the view from there.
  glm::vec3 origin_{0.0f};
  std::vector<glm::mat4> models_;
  glm::mat4 view_{1.0f};
  std::string preparedFor_;
  std::vector<bool> convex_;  // per primitive, from its mesh (isConvex)
  std::vector<std::pair<glm::vec3, glm::vec3>> boxes_;  // per primitive, its object-space bounding box
  std::vector<BoundingSphere> spheres_;                 // and bounding sphere
  // The work buffer: depth and stencil, the pass stepper's colour, and per pixel the primitive
  // whose fragment wrote the depth (its index + 1; 0 none), which the merge draws alone.
  GLuint work_ = 0, workDepth_ = 0, workColour_ = 0, workPrimitive_ = 0;
  // The automatic method's layered products: the nearest of their layers' surfaces, a buffer made
  // as the work buffer is (the two swap).
  GLuint nearest_ = 0, nearestDepth_ = 0, nearestColour_ = 0, nearestPrimitive_ = 0;
  glm::ivec2 workSize_{0};
  bool frameToClear_ = false;  // the frame not yet cleared this frame (clearFrame)
  bool mirroredView_ = false;  // this frame's view matrix has a negative determinant
  std::vector<bool> pastFar_;  // per primitive, whether the far plane may cut it: drawn depth clamped
  bool depthClamped_ = false;  // GL_DEPTH_CLAMP now
  DepthMapping depth_;         // this frame's: its depth tests, clear depth and projection
  // The depth tests that pass behind the buffer's depth (GL_GREATER, GL_GEQUAL; GL_LESS and
  // GL_LEQUAL in reversed depth, where nearer is greater) and the nearest depth there is.
  GLenum further() const { return depth_.less == GL_LESS ? GL_GREATER : GL_LESS; }
  GLenum furtherOrEqual() const { return depth_.lequal == GL_LEQUAL ? GL_GEQUAL : GL_LEQUAL; }
  double nearest() const { return 1.0 - depth_.farthest; }
  // The queries option, where the frame can wait for a query's result (the browser's come after it).
  static bool queriesWait(const Frame& f) { return f.on("queries") && f.features.samplesPassed; }
};

// ---- classroom.cpp ------------------------------------------------------------------------------

// The scene the options (or --scene's file) ask for, at the frame's time. Throws UsageError for
// a scene file with method 0.
CsgScene sceneFor(const Frame&, const Scene* fromFile);

// Whether a closed mesh bounds a convex solid (geometry/shadow_volume.h's isConvex on the mesh
// welded by position): SCS takes only these, and Goldfeather tries one layer of them.
bool convexMesh(const Mesh& mesh);

// ---- refusals.cpp ------------------------------------------------------------------------------

// Per primitive, whether a product of the sum names it: the primitives the expression draws.
std::vector<bool> primitivesUsed(const SumOfProducts& sop, std::size_t count);

// A product as the csg line writes it ("a * b - c"), its first few primitives where it has many.
std::string productText(const CsgProduct& p, const CsgScene& scene);

// The lesson's name, options, variants (with their cameras) and passes.
LessonInfo lessonInfo();

}  // namespace stencil::csg_lesson
