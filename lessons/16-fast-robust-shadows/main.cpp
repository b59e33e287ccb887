// Lesson 16: fast, practical and robust shadow volumes (McGuire, Hughes, Egan, Kilgard and
// Everitt, "Fast, Practical and Robust Shadows", 2003).
//
// Lessons 07-09 counted volume faces in front of the scene (z-pass), which breaks when the eye,
// or the near plane, lies in a shadow. Counting the faces behind the scene instead (z-fail)
// never meets the near plane, but needs the volume closed at both ends, caps that cost a
// triangle per caster face. The paper's system pays only where it must. Its pieces, in its
// order, in this file and in common/ (geometry/fast_shadows.h declares them in nearly this order):
//   1. the doubled vertex array: each caster vertex with w = 1 and w = 0, so a volume is indices
//      only (doubledVertexArray; on the GPU gl/doubled_caster.h, held by the lesson's Caster in
//      fast_robust_shadows.h; shaders/common/extrude.vert sends the w = 0 copies to infinity
//      away from the light);
//   2. the possible silhouette: edges between a face towards and a face away from the light,
//      found in object space (possibleSilhouette below; facesLight and possibleSilhouetteEdges)
//      and extruded into side quads that face out of the volume (sideIndices);
//   3. the case from the occlusion pyramid, from the light to the camera's near rectangle
//      (nearRectangle, occlusionPyramid, shadowCases): outside it z-pass with the sides alone
//      (case 1), inside it z-fail with a dark cap, and the light cap only where the caster may
//      be on screen (case 3, not 2). recipeFor is the one function that decides (but for a
//      caster that could nest past an 8-bit count, which buildVolume closes in pieces);
//   4. the dark cap as a fan over the silhouette at infinity (fanDarkCap; closeAroundLight for a
//      light inside the caster's hull), and
//   5. the light cap, the caster's lit faces (lightCapIndices): volumeOf puts the sides and both
//      caps together as indices into the doubled vertex array;
//   6. the light's bounds (lightClip): casters that miss them culled, the light's passes
//      scissored to their rectangle on screen, depth-bounded where the driver has
//      EXT_depth_bounds_test;
//   7. the rendering system of section 8 (render below): an ambient pass fills the depth
//      buffer, then per light the stencil cleared, its volumes counted (countVolume has the
//      stencil operations), the casters' sides turned from it marked shadowed (markTurnedFromLight:
//      the rule the count states, made to hold where its sides round), and its light added where
//      the stencil is 0, into a float target
//      (gl/accumulation_target.h) so many lights do not band.
// Scene files may also bring open meshes, whose faces block light from both sides (a volume
// from each side), and more nested volumes than 8 bits count (buildVolume, countVolumes).
// Where the driver has clip control (core in GL 4.5) the depth buffer is a float and the depth
// reversed (1 at the near plane, 0 at infinity; see lesson 15): LESS becomes GREATER, LEQUAL
// GEQUAL, and a tiny near plane keeps its precision. The variant pinf-fixed24 keeps the old path.
// The options, variants, built-in scene, overlays and --stats counts are in classroom.cpp.

#include <algorithm>
#include <memory>
#include <string>

#include "fast_robust_shadows.h"
#include "gl/errors.h"
#include "gl/light_shading.h"

namespace stencil::fast_robust_shadows {

// ---- 1. the doubled vertex array ------------------------------------------------------------

FastRobustShadows::FastRobustShadows(const Scene* fromFile)
    : extrude_("common/extrude.vert", "common/flat.frag"), flat_("common/flat.vert", "common/flat.frag") {
  if (fromFile) setScene(*fromFile);
}

// Each caster's welded vertices doubled on the GPU once (DoubledCaster: index i is (p_i, 1), n + i
// is (p_i, 0)), with what the lights will ask of it: its bounds and whether it is convex.
void FastRobustShadows::setScene(const Scene& scene) {
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

// ---- 2. the possible silhouette -------------------------------------------------------------

namespace {

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

}  // namespace

// ---- 7. the rendering system (section 8), with 6. the light's bounds ------------------------

void FastRobustShadows::render(Frame& f) {
  prepare(f);
  startCounts(f);
  framework_ = f.framebuffer();  // every pass ends copied into it
  // The depth mapping, before anything is cleared or drawn: reversed float depth where the
  // driver has clip control (lesson 15), every depth test and the projection following it.
  depth_ = depthMappingOf(f);
  if (f.reversedDepth) glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // window depth = clip z / w
  glClearDepth(depth_.farthest);                                      // 0 reversed: infinity
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
  glDepthFunc(depth_.less);
  // Rooms: a closed caster around the eye is a shell seen from inside (geometry/solid.h).
  solids_ = solidsSeenFrom(scene_, models, f.eye);
  if (!solids_.refusal.empty()) throw UsageError(solids_.refusal);
  glEnable(GL_CULL_FACE);  // a closed object's back faces are hidden, unless the near plane cuts it
  const glm::vec3 ambient =
      fromFile_ ? scene_.ambient : glm::vec3(0.01f * static_cast<float>(f.option("ambient")));
  meshes_.draw(scene_, depth_.projection * f.view, f.eye, glm::vec4(0, 1, 0, 0), glm::vec3(0), kInfinity,
               ambient);
  endPass(f, "ambient");

  // ---- per light: its shadow in the stencil, then its light where the stencil is 0 ----------
  const Frustum frustum = viewFrustum(viewProjection, false);
  const std::array<glm::vec3, 4> nearRect = nearRectangle(viewProjection);
  const std::vector<int> order = lightOrder(f);
  for (int index : order) {  // the chosen light last: the frame ends with its stencil
    const SceneLight& light = scene_.lights[static_cast<std::size_t>(index)];
    // The passes say whose they are, numbered as the light option [L] numbers them; the chosen
    // light, drawn last, says so (the stepper shows 1, 2, 3, then 0 where L is 0).
    const std::string which =
        "light " + std::to_string(index) + (index == order.back() ? ", chosen [L]" : "");
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
      // The old 24-bit path (pinf-fixed24, or no clip control) keeps the count alone.
      if (f.on("mark") && f.reversedDepth) markTurnedFromLight(f, light.position);
    }
    if (depthBounds) glDisable(GL_DEPTH_BOUNDS_TEST_EXT);
    endPass(f, "shadows", which, index);
    if (f.on("fill") && f.on("shadow")) {  // the fill the stencil test saw, for --stats
      drawVolumeFill(f, light.position);
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
    meshes_.draw(scene_, depth_.projection * f.view, f.eye, light.position, light.colour, light.radius,
                 glm::vec3(0));  // with its own fall-off
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_SCISSOR_TEST);
    glDepthFunc(depth_.less);
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

// ---- 3. the case from the occlusion pyramid -------------------------------------------------

// Every caster's volume for one light (world, homogeneous), into lightVolumes_ and uploaded.
void FastRobustShadows::buildVolumes(Frame& f, const glm::vec4& light, const LightClip& clip,
                                     const Frustum& pyramid, const Frustum& frustum) {
  // 3. Each caster's case, 0 where it misses the light's bounds; Lengyel's choice needs them all.
  std::vector<BoundingSphere> world;
  for (const Caster& c : casters_) world.push_back(worldBounds(c.bounds, meshes_.models()[c.object]));
  const std::vector<int> cases = shadowCases(world, clip, pyramid, frustum);
  const bool inPyramid = anyInPyramid(cases);
  const auto method = static_cast<ShadowMethod>(f.option("method"));
  lightVolumes_.clear();
  for (std::size_t c = 0; c < casters_.size(); ++c) {
    const std::size_t first = lightVolumes_.size();
    // A room is convex (solidsSeenFrom checks): nothing inside it is in its shadow, and its
    // volume would hold infinity.
    const bool room = solids_.room[casters_[c].object];
    if (cases[c] != 0 && !room)
      buildVolume(f, c, light, cases[c],
                  recipeFor(method, cases[c], inPyramid, f.on("light-cap"), light.w == 0.0f));
    recordCaster(f, casters_[c], cases[c], room, first);
  }
}

// ---- 4 and 5. the fan dark cap and the light cap: one caster's volume -----------------------

// One caster's volume: 2, 4 and 5 above; where it could nest deeper than a count group's 127,
// in pieces of its light cap instead, each closed by both of Everitt and Kilgard's caps.
void FastRobustShadows::buildVolume(Frame& f, std::size_t c, const glm::vec4& worldLight, int shadowCase,
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
  const std::size_t nesting = nestingOf(caster, p, light, lit, edges);
  std::vector<LightVolume> volumes{{c, 0, built.volume, nesting, false}};
  if (nesting > 127 && p.report.closedManifold()) {
    volumes.clear();
    built.indices.clear();
    built.split.clear();
    const Recipe full{true, light.w == 0.0f ? DarkCapKind::None : DarkCapKind::Piece, true};
    for (const LitPiece& piece : litFacePieces(p.mesh, p.adjacency, lit, light, 127)) {
      VolumeIndices v =
          volumeOf(p, light, full, piece.lit, possibleSilhouetteEdges(p.adjacency, piece.lit), false);
      v.volume.shadowCase = shadowCase;
      volumes.push_back({c, built.indices.size(), v.volume, piece.nesting, true});
      built.indices.insert(built.indices.end(), v.indices.begin(), v.indices.end());
    }
  }
  caster.gpu->upload(built.indices, built.split);
  caster.volume = volumes.front().volume;
  lightVolumes_.insert(lightVolumes_.end(), volumes.begin(), volumes.end());
}

// The most a caster's volume adds to a pixel's count (geometry/shadow_volume.h's nestingBound, and
// for a closed caster projectedNestingBound: its silhouette seen from the light).
std::size_t FastRobustShadows::nestingOf(const Caster& c, const PreparedCaster& p, const glm::vec4& light,
                                         const std::vector<bool>& lit, const std::vector<SilhouetteEdge>& edges) {
  if (c.convex) return 1;
  const bool outside =
      light.w == 0.0f || glm::distance(glm::vec3(light) / light.w, c.bounds.centre) > c.bounds.radius;
  // An open caster casts from both sides, and a fold of it changes the count by two.
  if (!p.report.closedManifold())
    return nestingBound(p.mesh.indices.size() / 3, 2 * edges.size(), false, outside);
  const std::size_t bound =
      nestingBound(static_cast<std::size_t>(std::count(lit.begin(), lit.end(), true)), edges.size(), false, outside);
  return bound <= 1 ? bound : std::min(bound, projectedNestingBound(p.mesh, lit, edges, light));
}

// ---- counting the volumes in the stencil ----------------------------------------------------

// Every volume of the light counted; where their counts could add past 255 (an 8-bit count
// would wrap to 0, lit), in groups that cannot pass 127, each folded into bit 7.
void FastRobustShadows::countVolumes(Frame& f, const glm::vec4& light) {
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // only the stencil changes
  glDepthMask(GL_FALSE);                                // volumes are not surfaces
  glDepthFunc(depth_.less);                             // in front of the scene: pass; behind: fail
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
void FastRobustShadows::countVolume(const Frame& f, const LightVolume& lv, const glm::vec4& worldLight) {
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
    glDepthFunc(depth_.less);
  }
}

// A caster's side turned from the light, where the eye sees it, lies in the caster's own shadow:
// the light reaches it through the caster. Its volume says so with a count of 1 or more, but
// near the terminator, on faces a few hundredths or less from edge-on, the sides of the possible
// silhouette run within a few millionths of the eye's distance behind the surface, and the
// rasterizer's depths can round one in front of it: a pixel counted 0, lit. Bit 7 set where such
// a face reads 0 (facesTurnedFromLight, decided per face as facesLight decides), at exactly its
// depths (GL_EQUAL, the ambient pass's program), makes the rule hold whatever the count rounded to.
void FastRobustShadows::markTurnedFromLight(Frame& f, const glm::vec4& light) {
  const bool parallel = f.projection[2][3] == 0.0f;  // clip w does not depend on depth
  const glm::vec4 eye = parallel ? glm::vec4(glm::vec3(glm::inverse(f.view)[2]), 0.0f) : glm::vec4(f.eye, 1.0f);
  glEnable(GL_STENCIL_TEST);
  // Only where the count reads 0: bit 7 set there (INVERT through the mask), every other
  // count kept as it is.
  glStencilMask(0x80);
  glStencilFunc(GL_EQUAL, 0, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);
  glDepthFunc(GL_EQUAL);
  f.count("mark_triangles", meshes_.drawTurnedFromLight(scene_, depth_.projection * f.view, light, eye));
  glDepthFunc(depth_.less);
  glStencilMask(0xFF);
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_CULL_FACE);  // the scene's own culling again
}

// Where a group's count (bits 0-6) is not 0, the pixel is in a shadow: set bit 7 and clear the
// count for the next group. A rectangle over the whole window, testing only the stencil.
void FastRobustShadows::foldCount() {
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
void FastRobustShadows::setExtrusion(const Frame& f, const Caster& c, const glm::vec4& worldLight) {
  const glm::mat4& model = meshes_.models()[c.object];
  extrude_.set("viewProjection", viewProjectionFrom(depth_.projection * f.view, drawingOrigin(f.eye)));
  extrude_.set("origin", drawingOrigin(f.eye));  // as meshes_.draw's
  extrude_.set("model", model);
  extrude_.set("light", glm::inverse(model) * worldLight);
}

// ---- the frame around them ------------------------------------------------------------------

// Every pass ends in the framework's framebuffer, where its snapshot, the stencil pictures and
// the shadow mask of light `mask` (-1: none) are read. Whatever Frame::pass and shadowMask leave
// bound, the lesson draws on into its target: the one place it binds it again.
void FastRobustShadows::endPass(Frame& f, const char* name, const std::string& detail, int mask) {
  target_->copyTo(framework_);
  f.pass(name, detail);
  if (mask >= 0) f.shadowMask("light-" + std::to_string(mask));
  target_->bind();
}

// The built-in scene follows the options that shape it.
void FastRobustShadows::prepare(const Frame& f) {
  if (fromFile_) return;
  const int key = f.option("slices") * 4 + f.option("many") * 2 + f.option("moving");
  if (key == sceneKey_) return;
  sceneKey_ = key;
  setScene(builtInScene(f.option("slices"), f.on("many"), f.on("moving")));
}

// Every light once, the chosen one last.
std::vector<int> FastRobustShadows::lightOrder(const Frame& f) const {
  const int n = static_cast<int>(scene_.lights.size());
  const int last = std::min(f.option("light"), n - 1);
  std::vector<int> order;
  for (int i = 0; i < n; ++i)
    if (i != last) order.push_back(i);
  order.push_back(last);
  return order;
}

}  // namespace stencil::fast_robust_shadows

int main(int argc, char** argv) {
  using namespace stencil::fast_robust_shadows;
  return stencil::runSceneLesson(
      lessonInfo(),
      [](const stencil::Scene* fromFile) { return std::make_unique<FastRobustShadows>(fromFile); }, argc,
      argv);
}
