// Lesson 16: fast, practical and robust shadow volumes (McGuire, Hughes, Egan, Kilgard and
// Everitt, "Fast, Practical and Robust Shadows", 2003).
//
// Lessons 07-09 counted volume faces in front of the scene (z-pass), which breaks when the eye,
// or the near plane, lies in a shadow. Counting the faces behind the scene instead (z-fail)
// never meets the near plane, but needs the volume closed at both ends, caps that cost a
// triangle per caster face. The paper's system pays only where it must. Its pieces, in its
// order, in this file and in common/ (read geometry/fast_shadows.h alongside: it declares them
// in nearly this order):
//   1. the doubled vertex array: each caster vertex with w = 1 and w = 0, so a volume is indices
//      only (doubledVertexArray; on the GPU gl/doubled_caster.h; shaders/common/extrude.vert
//      sends the w = 0 copies to infinity away from the light);
//   2. the possible silhouette: edges between a face towards and a face away from the light,
//      found in object space (geometry/shadow_volume.h's facesLight and possibleSilhouetteEdges) and
//      extruded into side quads that face out of the volume (sideIndices);
//   3. the case from the occlusion pyramid, from the light to the camera's near rectangle
//      (nearRectangle, occlusionPyramid, shadowCase): outside it z-pass with the sides alone
//      (case 1), inside it z-fail with a dark cap, and the light cap only where the caster may
//      be on screen (case 3, not 2). recipeFor below is the one place that decides;
//   4. the dark cap as a fan over the silhouette at infinity (fanDarkCap; closeAroundLight for a
//      light inside the caster's hull);
//   5. the light cap: the caster's lit faces (lightCapIndices);
//   6. the light's bounds (lightClip): casters that miss them culled, the light's passes
//      scissored to their rectangle on screen, depth-bounded where the driver has
//      EXT_depth_bounds_test;
//   7. the rendering system of section 8 (render below): an ambient pass fills the depth
//      buffer, then per light the stencil cleared, its volumes counted, and its light added
//      where the stencil is 0, into a float target (gl/accumulation_target.h) so many lights do
//      not band.
// Scene files may also bring open meshes, whose faces block light from both sides (a volume
// from each side), and more nested volumes than 8 bits count (geometry/shadow_volume.h's
// countPlan).
//
// Stencil recipe per light, one pass over both faces (two-sided stencil, no culling), depth
// LESS, depth and colour writes off:
//   z-pass (case 1)   front faces INCR_WRAP where the depth test passes, back faces DECR_WRAP;
//   z-fail (2 and 3)  back faces INCR_WRAP where the depth test fails, front faces DECR_WRAP;
//   light cap         drawn with depth func NEVER: it lies on the caster's own surface, never in
//                     front of what the depth buffer holds, so it must always take the fail path.
// Where the driver has clip control (core in GL 4.5) the depth buffer is a float and the depth
// reversed (1 at the near plane, 0 at infinity; see lesson 15): LESS becomes GREATER, LEQUAL
// GEQUAL, and a tiny near plane keeps its precision. The variant pinf-fixed24 keeps the old path.

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <memory>
#include <string>

#include "classroom.h"
#include "geometry/bounds.h"
#include "geometry/dual_silhouette.h"
#include "geometry/fast_shadows.h"
#include "geometry/projection.h"
#include "geometry/scene.h"
#include "geometry/shadow_volume.h"
#include "gl/accumulation_target.h"
#include "gl/doubled_caster.h"
#include "gl/errors.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/scene_meshes.h"
#include "gl/shader.h"

using namespace stencil;
using namespace stencil::fast_robust_shadows;  // classroom.h: the options, the built-in scene, overlays

namespace {

// ---- 1. the doubled vertex array --------------------------------------------------------------

// A caster, prepared once per scene: its welded vertices doubled on the GPU, so that each light
// only rewrites its index list.
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

// ---- 2. the possible silhouette ---------------------------------------------------------------

// The possible silhouette edges for a light in the caster's space, directed the way the lit face
// walks them. A closed caster's are found the way --set silhouettes says, the same edges each
// way: 0 brute force over its adjacency, 1 streaming passes (SilhouetteCaster), 2 a dual-space
// tree (DualSilhouettes). An open caster blocks light with both sides: its edges between the two
// kinds twice.
std::vector<SilhouetteEdge> possibleSilhouette(Caster& c, const PreparedCaster& p, const glm::vec4& light,
                                               const std::vector<bool>& lit, int how) {
  if (!p.report.closedManifold() || how == 0) return possibleSilhouetteEdges(p, lit);
  if (!c.streaming) c.streaming = std::make_unique<SilhouetteCaster>(prepareSilhouettes(p.mesh, p.adjacency));
  if (how == 1) return possibleSilhouetteEdges(*c.streaming, light);
  if (!c.dual) c.dual = std::make_unique<DualSilhouettes>(*c.streaming);
  std::vector<SilhouetteEdge> edges;
  c.dual->query(light, edges);
  return edges;
}

// ---- 3, 4 and 5. the case, and the volume it asks for -----------------------------------------
// In geometry/fast_shadows.h, GL-free, shared with lesson 13: shadowCases (each caster's case from
// the occlusion pyramid, 0 culled by the light's bounds), recipeFor (the one function from a
// method and a case to z-pass or z-fail, which dark cap, whether a light cap) and volumeOf (the
// sides, the fan dark cap and the light cap as indices into the doubled vertex array).

// ---- 7. the rendering system (section 8), with 6. the light's bounds --------------------------

class FastRobustShadows final : public Lesson {
 public:
  explicit FastRobustShadows(const Scene* fromFile)
      : extrude_("common/extrude.vert", "common/flat.frag"), flat_("common/flat.vert", "common/flat.frag") {
    if (fromFile) setScene(*fromFile);
  }

  void render(Frame& f) override {
    prepare(f);
    startCounts(f);
    framework_ = f.framebuffer();  // every pass ends copied into it
    setDepthMapping(f);            // before anything is cleared or drawn
    const ColourFormat colour = f.on("float") ? ColourFormat::RGBA16F : ColourFormat::RGBA8;
    const DepthFormat depth = f.reversedDepth ? DepthFormat::Float32 : DepthFormat::Fixed24;
    if (!target_ || !target_->fits(f.size, colour, depth))
      target_ = std::make_unique<AccumulationTarget>(f.size, colour, depth);
    target_->bind();
    // Frustum planes, the near rectangle and the light's bounds read GL's convention, not the
    // reversed matrix the frame draws with.
    const glm::mat4 viewProjection = f.projection * f.view;
    // A mirrored view turns every triangle round on screen: what faces the eye winds clockwise.
    glFrontFace(glm::determinant(f.view) < 0.0f ? GL_CW : GL_CCW);
    // Each object placed for this frame; closed ones the near plane cuts show their back faces.
    f.count("objects_cut_by_near_plane", meshes_.place(scene_, f.time, viewProjection));
    const std::vector<glm::mat4>& models = meshes_.models();

    // ---- ambient: the depth buffer filled once, for every light --------------------------------
    glClearColor(0.02f, 0.025f, 0.035f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);  // depth: the farthest
    glEnable(GL_DEPTH_TEST);                                                     // the nearest surface wins
    glDepthFunc(less_);
    // Rooms: a closed caster around the eye is a shell seen from inside (geometry/solid.h).
    solids_ = solidsSeenFrom(scene_, models, f.eye);
    if (!solids_.refusal.empty()) throw UsageError(solids_.refusal);
    glEnable(GL_CULL_FACE);  // a closed object's back faces are hidden, unless the near plane cuts it
    const glm::vec3 ambient =
        fromFile_ ? scene_.ambient : glm::vec3(0.01f * static_cast<float>(f.option("ambient")));
    meshes_.draw(scene_, projection_ * f.view, f.eye, glm::vec4(0, 1, 0, 0), glm::vec3(0), kInfinity,
                 ambient);
    endPass(f, "ambient");

    // ---- per light: its shadow in the stencil, then its light where the stencil is 0 ----------
    const Frustum frustum = viewFrustum(viewProjection, false);
    const std::array<glm::vec3, 4> nearRect = nearRectangle(viewProjection);
    for (int index : lightOrder(f)) {  // the chosen light last: the frame ends with its stencil
      const SceneLight& light = scene_.lights[static_cast<std::size_t>(index)];
      const std::string which = "light " + std::to_string(index);  // the passes say whose they are
      for (Caster& c : casters_) c.volume = {};
      // 6. The light's bounds: its sphere's rectangle on screen and the depths it spans.
      const LightClip clip =
          lightClip(light.position, light.radius, f.on("bounds"), f.view, f.projection, f.size);
      if (clip.offScreen()) {  // it adds nothing
        f.count("lights_offscreen");
        continue;
      }
      f.count("lights_drawn");
      glScissor(clip.scissor.x, clip.scissor.y, clip.scissor.width, clip.scissor.height);

      // The stencil cleared everywhere, so what the frame ends with is this light's alone.
      glStencilMask(0xFF);
      glClear(GL_STENCIL_BUFFER_BIT);
      if (f.on("shadow") && lightBuried(scene_, models, solids_, light.position)) {
        // A light inside a solid (outside the room the eye is in) lights nothing the eye sees:
        // its picture is all shadow, a count of 1 everywhere, and it adds no light.
        glClearStencil(1);
        glClear(GL_STENCIL_BUFFER_BIT);
        glClearStencil(0);
        f.count("lights_buried");
        endPass(f, "shadows", which, index);
        continue;
      }
      glEnable(GL_SCISSOR_TEST);  // from here on only the light's rectangle is touched
      const bool depthBounds = hasFeature(f.features, Feature::DepthBoundsTest) && clip.depthBounds;
      if (depthBounds) {  // volumes skip pixels whose surface lies in front of or behind the sphere
        glEnable(GL_DEPTH_BOUNDS_TEST_EXT);
        if (f.reversedDepth)  // the same bounds in reversed depth: d -> 1 - d, the order swapped
          glDepthBoundsEXT(1.0 - clip.depth.farthest, 1.0 - clip.depth.nearest);
        else
          glDepthBoundsEXT(clip.depth.nearest, clip.depth.farthest);
      }
      f.count(depthBounds ? "depth_bounds_used" : "depth_bounds_skipped");
      if (f.on("shadow")) {
        buildVolumes(f, light.position, clip, occlusionPyramid(nearRect, light.position), frustum);
        countVolumes(f, light.position);
      }
      if (depthBounds) glDisable(GL_DEPTH_BOUNDS_TEST_EXT);
      endPass(f, "shadows", which, index);
      if (f.on("fill") && f.on("shadow")) {  // the fill the stencil test saw, for --stats
        drawVolumeFill(light.position);
        endPass(f, "volume-fill", which);
      }

      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);  // the light's colour is added
      glDepthMask(GL_FALSE);                            // onto the surfaces already there
      glDepthFunc(GL_EQUAL);                            // exactly the ambient pass's surfaces
      glEnable(GL_STENCIL_TEST);
      glStencilFunc(GL_EQUAL, 0, 0xFF);        // outside every volume
      glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);  // the count stays for the next look
      glEnable(GL_BLEND);
      glBlendFunc(GL_ONE, GL_ONE);  // light adds up
      meshes_.draw(scene_, projection_ * f.view, f.eye, light.position, light.colour, light.radius,
                   glm::vec3(0));  // with its own fall-off
      glDisable(GL_BLEND);
      glDisable(GL_STENCIL_TEST);
      glDisable(GL_SCISSOR_TEST);
      glDepthFunc(less_);
      glDepthMask(GL_TRUE);
      endPass(f, "illumination", which);
    }
    recordLastLight(f);

    // ---- the classroom's view: cases, volumes, silhouettes of the light drawn last ------------
    if (f.option("stretch") > 0) {  // in the accumulation target, before RGBA16F is clamped to 8 bits
      stretchContrast(flat_, window_, f.option("stretch"));
      target_->copyTo(framework_);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framework_);
    if (f.on("tint")) tintShadow(flat_, window_);
    if (f.on("show")) drawOverlay(f);
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);  // GL's default again
    f.pass("overlay");
  }

 private:
  // One volume counted for the current light: a caster's whole volume, or one piece of it.
  struct LightVolume {
    std::size_t caster;
    std::size_t first;  // into the caster's uploaded indices
    CasterVolume volume;
    std::size_t nesting;  // the most it can add to a pixel's count
    bool piece;           // one piece of the caster's light cap
  };

  // Every caster's volume for one light (world, homogeneous), into lightVolumes_ and uploaded.
  void buildVolumes(Frame& f, const glm::vec4& light, const LightClip& clip, const Frustum& pyramid,
                    const Frustum& frustum) {
    // 3. Each caster's case, 0 where it misses the light's bounds; Lengyel's choice needs them all.
    std::vector<BoundingSphere> world;
    for (const Caster& c : casters_) world.push_back(worldBounds(c.bounds, meshes_.models()[c.object]));
    const std::vector<int> cases = shadowCases(world, clip, pyramid, frustum);
    const bool anyInPyramid = std::any_of(cases.begin(), cases.end(), [](int c) { return c > 1; });
    const auto method = static_cast<ShadowMethod>(f.option("method"));
    lightVolumes_.clear();
    for (std::size_t c = 0; c < casters_.size(); ++c) {
      const std::size_t first = lightVolumes_.size();
      // A room is convex (solidsSeenFrom checks): nothing inside it is in its shadow, and its
      // volume would hold infinity.
      const bool room = solids_.room[casters_[c].object];
      if (cases[c] != 0 && !room)
        buildVolume(f, c, light, cases[c],
                    recipeFor(method, cases[c], anyInPyramid, f.on("light-cap"), light.w == 0.0f));
      recordCaster(f, casters_[c], cases[c], room, first);
    }
  }

  // One caster's volume: 2, 4 and 5 above; where it could nest deeper than a count group's 127,
  // in pieces of its light cap instead, each closed by both of Everitt and Kilgard's caps.
  void buildVolume(Frame& f, std::size_t c, const glm::vec4& worldLight, int shadowCase,
                   const Recipe& recipe) {
    Caster& caster = casters_[c];
    const PreparedCaster& p = scene_.objects[caster.object].caster;
    const glm::vec4 light =
        glm::inverse(meshes_.models()[caster.object]) * worldLight;  // in the caster's space
    const std::vector<bool> lit = facesLight(p.mesh, light);
    const std::vector<SilhouetteEdge> edges =
        possibleSilhouette(caster, p, light, lit, f.option("silhouettes"));
    VolumeIndices built = volumeOf(p, light, recipe, lit, edges, f.on("split"));
    built.volume.shadowCase = shadowCase;
    const std::size_t nesting = nestingOf(caster, p, light, lit, edges.size());
    std::vector<LightVolume> volumes{{c, 0, built.volume, nesting, false}};
    if (nesting > 127 && p.report.closedManifold()) {
      volumes.clear();
      built.indices.clear();
      built.split.clear();
      const Recipe full{true, light.w == 0.0f ? DarkCapKind::None : DarkCapKind::Piece, true};
      for (const std::vector<bool>& piece : litFacePieces(lit, 127)) {
        VolumeIndices v = volumeOf(p, light, full, piece, possibleSilhouetteEdges(p.adjacency, piece), false);
        v.volume.shadowCase = shadowCase;
        volumes.push_back({c, built.indices.size(), v.volume,
                           static_cast<std::size_t>(std::count(piece.begin(), piece.end(), true)), true});
        built.indices.insert(built.indices.end(), v.indices.begin(), v.indices.end());
      }
    }
    caster.gpu->upload(built.indices, built.split);
    caster.volume = volumes.front().volume;
    lightVolumes_.insert(lightVolumes_.end(), volumes.begin(), volumes.end());
  }

  // The most a caster's volume adds to a pixel's count (geometry/shadow_volume.h's nestingBound).
  static std::size_t nestingOf(const Caster& c, const PreparedCaster& p, const glm::vec4& light,
                               const std::vector<bool>& lit, std::size_t edges) {
    if (c.convex) return 1;
    const bool outside =
        light.w == 0.0f || glm::distance(glm::vec3(light) / light.w, c.bounds.centre) > c.bounds.radius;
    // An open caster casts from both sides, and a fold of it changes the count by two.
    if (!p.report.closedManifold()) return nestingBound(p.mesh.indices.size() / 3, 2 * edges, false, outside);
    return nestingBound(static_cast<std::size_t>(std::count(lit.begin(), lit.end(), true)), edges, false,
                        outside);
  }

  // Every volume of the light counted; where their counts could add past 255 (an 8-bit count
  // would wrap to 0, lit), in groups that cannot pass 127, each folded into bit 7.
  void countVolumes(Frame& f, const glm::vec4& light) {
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // only the stencil changes
    glDepthMask(GL_FALSE);                                // volumes are not surfaces
    glDepthFunc(less_);                                   // in front of the scene: pass; behind: fail
    glDisable(GL_CULL_FACE);                              // both faces in one draw, two-sided stencil
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);  // every volume fragment counts
    std::vector<std::size_t> nesting;
    for (const LightVolume& lv : lightVolumes_) nesting.push_back(lv.nesting);
    const CountPlan plan = countPlan(nesting);
    for (int g = 0; g < plan.groups; ++g) {
      if (plan.fold) glStencilMask(0x7F);  // bit 7 keeps what the groups before found
      for (std::size_t k = 0; k < lightVolumes_.size(); ++k)
        if (plan.group[k] == g) countVolume(f, lightVolumes_[k], light);
      if (plan.fold) foldCount();
    }
    glStencilMask(0xFF);
    if (plan.fold) f.count("count_groups", static_cast<std::uint64_t>(plan.groups));
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_CULL_FACE);  // the scene's own culling again
  }

  // One volume counted: z-pass in front of the scene, or z-fail behind it.
  void countVolume(const Frame& f, const LightVolume& lv, const glm::vec4& worldLight) {
    const Caster& caster = casters_[lv.caster];
    const CasterVolume& v = lv.volume;
    setExtrusion(f, caster, worldLight);
    if (!v.zfail) {  // z-pass: count the faces in front of the scene
      glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);  // the eye ray enters a volume
      glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);   // and leaves it
      caster.gpu->draw(lv.first, v.sides);
    } else {  // z-fail: count the faces behind the scene, the volume closed at both ends
      glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);   // behind: the ray leaves a volume
      glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);  // behind: it enters one
      // The dark cap at infinity fails LESS (GREATER) by itself.
      caster.gpu->draw(lv.first, v.sides + v.darkCap);
      if (lv.first == 0) caster.gpu->drawSplit();
      glDepthFunc(GL_NEVER);  // the light cap lies on the caster's surface: never in front of it
      caster.gpu->draw(lv.first + v.sides + v.darkCap, v.lightCap);
      glDepthFunc(less_);
    }
  }

  // Where a group's count (bits 0-6) is not 0, the pixel is in a shadow: set bit 7 and clear the
  // count for the next group. A rectangle over the whole window, testing only the stencil.
  void foldCount() {
    glStencilMask(0xFF);
    glStencilFunc(GL_NOTEQUAL, 0x80, 0x7F);     // (0x80 & 0x7F) = 0 != count: counted something
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);  // 0x80: shadowed, count 0
    glDisable(GL_DEPTH_TEST);
    flat_.set("transform", glm::mat4(1.0f));  // the rectangle is in clip space already
    window_.draw();
    glEnable(GL_DEPTH_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
  }

  // extrude.vert's uniforms for one caster: its model matrix and the light in its space.
  void setExtrusion(const Frame& f, const Caster& c, const glm::vec4& worldLight) {
    const glm::mat4& model = meshes_.models()[c.object];
    extrude_.set("viewProjection", projection_ * f.view);
    extrude_.set("model", model);
    extrude_.set("light", glm::inverse(model) * worldLight);
  }

  // Every pass ends in the framework's framebuffer, where its snapshot, the stencil pictures and
  // the shadow mask of light `mask` (-1: none) are read. Whatever Frame::pass and shadowMask leave
  // bound, the lesson draws on into its target: the one place it binds it again.
  void endPass(Frame& f, const char* name, const std::string& detail = {}, int mask = -1) {
    target_->copyTo(framework_);
    f.pass(name, detail);
    if (mask >= 0) f.shadowMask("light-" + std::to_string(mask));
    target_->bind();
  }

  // ---- the scene -------------------------------------------------------------------------------

  void setScene(const Scene& scene) {
    scene_ = scene;
    fromFile_ = !scene.file.empty();
    casters_.clear();
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
      SceneObject& o = scene_.objects[i];
      if (!o.casts) continue;
      if (o.caster.mesh.positions.empty()) o.caster = prepareCaster(o.mesh);
      Caster& c = casters_.emplace_back();
      c.object = i;
      c.bounds = boundingSphereOf(o.caster.mesh.positions);
      c.gpu = std::make_unique<DoubledCaster>(o.caster.mesh);
      c.convex = isConvex(o.caster.mesh, o.caster.adjacency);
    }
    meshes_.set(scene_);
  }

  // The built-in scene follows the options that shape it.
  void prepare(const Frame& f) {
    if (fromFile_) return;
    const int key = f.option("slices") * 4 + f.option("many") * 2 + f.option("moving");
    if (key == sceneKey_) return;
    sceneKey_ = key;
    setScene(builtInScene(f.option("slices"), f.on("many"), f.on("moving")));
  }

  // Reversed float depth or GL's mapping, as the frame says; every depth comparison follows it.
  // Reversed: window depth is clip z / w, 1 at the near plane and n/d at distance d, which the
  // float depth buffer holds to about 2^-24 of d at every distance.
  void setDepthMapping(const Frame& f) {
    if (f.reversedDepth) {
      glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // window depth = clip z / w: no 0.5 + 0.5 z/w
      glClearDepth(0.0);                             // the farthest depth is 0 (infinity)
      less_ = GL_GREATER;                            // nearer is greater
      lequal_ = GL_GEQUAL;
      projection_ = reversedDepth(f.projection);  // clip z' = (w - z) / 2: near 1, infinity 0
    } else {                                      // GL's default clip control, as the framework leaves it
      glClearDepth(1.0);
      less_ = GL_LESS;
      lequal_ = GL_LEQUAL;
      projection_ = f.projection;
    }
  }

  // Every light once, the chosen one last.
  std::vector<int> lightOrder(const Frame& f) const {
    const int n = static_cast<int>(scene_.lights.size());
    const int last = std::min(f.option("light"), n - 1);
    std::vector<int> order;
    for (int i = 0; i < n; ++i)
      if (i != last) order.push_back(i);
    order.push_back(last);
    return order;
  }

  // ---- the classroom's view --------------------------------------------------------------------

  // The casters coloured by their case for the light drawn last (grey culled, green 1, amber 2,
  // red 3), their volumes translucent in the same colour, their silhouettes as lines.
  void drawOverlay(const Frame& f) {
    const glm::vec4 caseColour[4] = {{0.5f, 0.5f, 0.5f, 0.55f},
                                     {0.2f, 0.85f, 0.3f, 0.55f},
                                     {1.0f, 0.7f, 0.1f, 0.55f},
                                     {1.0f, 0.15f, 0.1f, 0.55f}};
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(lequal_);
    glDepthMask(GL_FALSE);  // the overlay changes no depth (and, stencil test off, no stencil)
    glEnable(GL_POLYGON_OFFSET_FILL);
    // The tint lies on the caster, drawn by another shader: pulled towards the eye, which is
    // towards smaller depths in GL's mapping and larger ones reversed.
    const float towardsEye = f.reversedDepth ? 1.0f : -1.0f;
    glPolygonOffset(towardsEye, towardsEye);
    for (const Caster& c : casters_) {
      flat_.set("transform", projection_ * f.view * meshes_.models()[c.object]);
      flat_.set("colour", caseColour[c.volume.shadowCase]);
      meshes_.drawObject(c.object);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_CULL_FACE);  // both sides of the volumes show
    const SceneLight& light = scene_.lights[static_cast<std::size_t>(lightOrder(f).back())];
    for (const Caster& c : casters_) {
      const CasterVolume& v = c.volume;
      if (v.shadowCase == 0) continue;
      setExtrusion(f, c, light.position);
      extrude_.set("colour", glm::vec4(glm::vec3(caseColour[v.shadowCase]), 0.12f));
      c.gpu->draw(0, v.sides + v.darkCap + v.lightCap);
      c.gpu->drawSplit();
      extrude_.set("colour", glm::vec4(1.0f, 1.0f, 0.6f, 1.0f));
      glDepthFunc(GL_ALWAYS);  // the silhouettes show through their casters
      c.gpu->draw(v.sides + v.darkCap + v.lightCap, v.silhouette, GL_LINES);
      glDepthFunc(lequal_);
    }
    glDisable(GL_BLEND);
    glDepthFunc(less_);
    glDepthMask(GL_TRUE);
  }

  // ---- test hooks: --stats counts, the volume-fill measure, the oracle ---------------------------

  // The counts --stats reports, present in every frame whatever happens in it.
  static void startCounts(Frame& f) {
    for (const char* name :
         {"lights_drawn", "lights_offscreen", "casters_culled", "casters_case1", "casters_case2",
          "casters_case3", "casters_zfail", "side_triangles", "dark_cap_triangles", "light_cap_triangles",
          "split_fan_triangles", "fan_spheres", "depth_bounds_used", "depth_bounds_skipped",
          "objects_cut_by_near_plane", "rooms", "lights_buried"})
      f.count(name, 0);
  }

  // What one caster cost the light being drawn: skipped (case 0, culled by the light's bounds; or
  // a room), or its case, its silhouette query and its volumes, lightVolumes_ from `first` on.
  void recordCaster(Frame& f, const Caster& c, int shadowCase, bool room, std::size_t first) const {
    if (shadowCase == 0) return f.count("casters_culled");
    if (room) return f.count("rooms");
    f.count("casters_case" + std::to_string(shadowCase));
    if (c.dual && f.option("silhouettes") == 2) {
      f.count("dual_cells_visited", c.dual->lastQuery().cellsVisited);
      f.count("dual_edges_tested", c.dual->lastQuery().edgesTested);
    }
    if (lightVolumes_[first].piece) f.count("volume_pieces", lightVolumes_.size() - first);
    for (std::size_t k = first; k < lightVolumes_.size(); ++k) {
      const CasterVolume& v = lightVolumes_[k].volume;
      if (v.zfail) f.count("casters_zfail");
      f.count("side_triangles", v.sides / 3);
      f.count("dark_cap_triangles", v.darkCap / 3 + v.splitVertices / 3);
      f.count("light_cap_triangles", v.lightCap / 3);
      f.count("split_fan_triangles", v.splitTriangles);
      f.count("fan_spheres", static_cast<std::uint64_t>(v.spheres));
    }
  }

  // Per caster, for the light drawn last: its case (0 culled) and what its volume cost.
  void recordLastLight(Frame& f) const {
    for (const Caster& c : casters_) {
      const std::string& name = scene_.objects[c.object].name;
      f.count("case." + name, static_cast<std::uint64_t>(c.volume.shadowCase));
      f.count("sides." + name, c.volume.sides / 3);
      f.count("dark_cap." + name, c.volume.darkCap / 3 + c.volume.splitVertices / 3);
      f.count("light_cap." + name, c.volume.lightCap / 3);
    }
  }

  // The light's volumes once more, every fragment passing: nothing written, only counted by the
  // pass's occlusion query. The same geometry and scissor as the shadows pass.
  void drawVolumeFill(const glm::vec4& light) {
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glDisable(GL_DEPTH_TEST);  // in front of the scene or behind, every fragment is fill
    glDisable(GL_CULL_FACE);
    for (const LightVolume& lv : lightVolumes_) {
      const CasterVolume& v = lv.volume;
      const glm::mat4& model = meshes_.models()[casters_[lv.caster].object];
      extrude_.set("model", model);
      extrude_.set("light", glm::inverse(model) * light);
      casters_[lv.caster].gpu->draw(lv.first, v.sides + v.darkCap + v.lightCap);
      if (lv.first == 0) casters_[lv.caster].gpu->drawSplit();
    }
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
  }

 public:
  std::optional<ShadowCheck> shadowCheck(const Frame& f) const override {
    if (!f.on("shadow") || scene_.lights.empty()) return std::nullopt;
    const SceneLight& light = scene_.lights[static_cast<std::size_t>(lightOrder(f).back())];
    ShadowCheck check{{}, light.position, [](std::uint8_t s) { return s == 0; }, true};
    if (f.on("bounds")) check.lightRadius = light.radius;
    for (const SceneObject& o : scene_.objects)
      check.objects.push_back({&o.mesh, o.modelAt(f.time), o.casts, o.receives});
    return check;
  }

 private:
  SceneMeshes meshes_;  // the objects, shaded
  Program extrude_, flat_;
  GLenum less_ = GL_LESS, lequal_ = GL_LEQUAL;  // the depth tests of this frame's depth mapping
  glm::mat4 projection_{1.0f};                  // what the frame draws with: f.projection, maybe reversed
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

}  // namespace

int main(int argc, char** argv) {
  return runSceneLesson(
      lessonInfo(), [](const Scene* fromFile) { return std::make_unique<FastRobustShadows>(fromFile); }, argc,
      argv);
}
