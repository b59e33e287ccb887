// Lesson 16's parts: the caster as the lesson keeps it, and the lesson itself. main.cpp defines the
// algorithm, in the paper's order; classroom.cpp what surrounds it (the options, variants and
// cameras a class chooses from, the built-in scene, the overlays, and the counts --stats reports),
// none of which changes how a shadow is counted.
#pragma once
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/bounds.h"
#include "geometry/dual_silhouette.h"
#include "geometry/fast_shadows.h"
#include "geometry/scene.h"
#include "geometry/shadow_volume.h"
#include "geometry/solid.h"
#include "gl/accumulation_target.h"
#include "gl/depth_mapping.h"
#include "gl/doubled_caster.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/scene_meshes.h"
#include "gl/shader.h"

namespace stencil::fast_robust_shadows {

// 1. The doubled vertex array: a caster, prepared once per scene, its welded vertices doubled on
// the GPU, so that each light only rewrites its index list.
struct Caster {
  std::size_t object = 0;              // in the scene
  BoundingSphere bounds;               // object space
  std::unique_ptr<DoubledCaster> gpu;  // doubledVertexArray, and this light's indices
  bool convex = false;                 // its volume nests once
  // --set silhouettes=1 or 2 builds these on first use; the tree reads the streaming caster.
  std::unique_ptr<SilhouetteCaster> streaming;
  std::unique_ptr<DualSilhouettes> dual;
  CasterVolume volume;  // for the light being drawn; after the loop, the light drawn last's
};

// One volume counted for the current light: a caster's whole volume, or one piece of it.
struct LightVolume {
  std::size_t caster;
  std::size_t first;  // into the caster's uploaded indices
  CasterVolume volume;
  std::size_t nesting;  // the most it can add to a pixel's count
  bool piece;           // one piece of the caster's light cap
};

class FastRobustShadows final : public Lesson {
 public:
  explicit FastRobustShadows(const Scene* fromFile);
  void render(Frame& f) override;  // 7. the rendering system of section 8

 private:
  // Each defined with its comment.
  // ---- main.cpp: the algorithm -------------------------------------------------------------------
  void buildVolumes(Frame& f, const glm::vec4& light, const LightClip& clip, const Frustum& pyramid,
                    const Frustum& frustum);
  void buildVolume(Frame& f, std::size_t c, const glm::vec4& worldLight, int shadowCase,
                   const Recipe& recipe);
  static std::size_t nestingOf(const Caster& c, const PreparedCaster& p, const glm::vec4& light,
                               const std::vector<bool>& lit, const std::vector<SilhouetteEdge>& edges);
  void countVolumes(Frame& f, const glm::vec4& light);
  void countVolume(const Frame& f, const LightVolume& lv, const glm::vec4& worldLight);
  void markTurnedFromLight(Frame& f, const glm::vec4& light);
  void foldCount();
  void setExtrusion(const Frame& f, const Caster& c, const glm::vec4& worldLight);
  void endPass(Frame& f, const char* name, const std::string& detail = {}, int mask = -1);
  void setScene(const Scene& scene);
  void prepare(const Frame& f);
  std::vector<int> lightOrder(const Frame& f) const;

  // ---- classroom.cpp: the overlay, the counts --stats reports, the oracle's claim -----------------
  void drawOverlay(const Frame& f);
  static void startCounts(Frame& f);
  void recordCaster(Frame& f, const Caster& c, int shadowCase, bool room, std::size_t first) const;
  void recordLastLight(Frame& f) const;
  void drawVolumeFill(const Frame& f, const glm::vec4& light);

 public:
  std::optional<ShadowCheck> shadowCheck(const Frame& f) const override;

 private:
  SceneMeshes meshes_;  // the objects, shaded
  Program extrude_, flat_;
  DepthMapping depth_;  // this frame's: its depth tests and the projection it draws with
  Scene scene_;
  bool fromFile_ = false;
  int sceneKey_ = -1;
  SolidsSeen solids_;  // this frame's rooms
  std::vector<Caster> casters_;
  std::vector<LightVolume> lightVolumes_;  // the current light's
  WindowRectangle window_;                 // the whole window, for folding the count and the overlays
  std::unique_ptr<AccumulationTarget> target_;
  GLuint framework_ = 0;
};

// ---- classroom.cpp ------------------------------------------------------------------------------

// The lesson's name, options, variants (with their cameras) and passes.
LessonInfo lessonInfo();

// In the spirit of the paper's figures: stairs, a grid of cubes, a sphere of `slices` slices, two
// moving casters (`moving`), and four coloured lights, one of them directional, or (`many`) a
// ring of thirty-two dim point lights.
Scene builtInScene(int slices, bool many, bool moving);

// The light sum doubled `times` times in the bound colour buffer, so that 8-bit bands show.
void stretchContrast(const Program& flat, const WindowRectangle& window, int times);

// A blue tint where the stencil is not 0 (the light drawn last is blocked). Writes colour only.
void tintShadow(const Program& flat, const WindowRectangle& window);

}  // namespace stencil::fast_robust_shadows
