// Lesson 16 around its algorithm: the options, variants and cameras a class chooses from, the
// built-in scene, the overlays and the counts --stats reports. None changes how a shadow is counted.
#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "fast_robust_shadows.h"
#include "geometry/shapes.h"

namespace stencil::fast_robust_shadows {
namespace {

constexpr int kManyLights = 32;
// The ambient light, in hundredths, of the views from inside the sphere's shadow: there the warm
// light is behind the sphere, and at the default 0.12 most of the picture is near black.
constexpr int kShadowAmbient = 40;
// Objects on the ground stand a little into it: a silhouette edge lying in the ground's plane
// would extrude into a side face coplanar with the ground there, whose depth test is a toss-up.
constexpr float kSunk = 0.01f;

// A camera at `eye` looking at `target`, the far plane at infinity.
OrbitCamera lookingFrom(glm::vec3 eye, glm::vec3 target) {
  SceneCamera c;
  c.eye = eye;
  c.target = target;
  c.fovyDeg = 70.0f;
  return orbitCameraOf(c);
}

// Where the eye sits in the sphere's shadow from the warm light: on the line from the light
// through the sphere's centre, past the sphere, a little above the ground.
glm::vec3 underTheSphere() {
  const glm::vec3 light(-2.0f, 4.6f, 2.4f), sphere(-0.4f, 1.3f, 1.2f);
  return light + 1.3f * (sphere - light);
}
// Looking away from the light, over the cubes: the near plane lies in the sphere's volume, so
// z-pass alone fails; the sphere is in the occlusion pyramid but out of view (case 2).
OrbitCamera eyeInShadow() {
  return lookingFrom(underTheSphere(), {2.0f, 0.3f, -1.6f});
}
// Half a unit aside, looking up past the sphere at the stairs: the sphere in case 3.
OrbitCamera lookingUp() {
  return lookingFrom(underTheSphere() + glm::vec3(0.5f, 0.0f, 0.0f), {-2.5f, 1.6f, 0.9f});
}

}  // namespace

Scene builtInScene(int slices, bool many, bool moving) {
  using glm::translate;
  const glm::mat4 id(1.0f);
  Scene s;
  s.objects.push_back(sceneObject("ground", makePlane(7.0f, 1), id, {0.75f, 0.74f, 0.7f}, false));
  s.objects.push_back(
      sceneObject("stairs", makeStairs(6, 2.2f, 0.3f, 0.45f),
                  glm::rotate(translate(id, {-3.2f, 0.9f - kSunk, 0.25f}), glm::radians(90.0f), {0, 1, 0}),
                  {0.7f, 0.6f, 0.5f}));
  for (int i = 0; i < 9; ++i) {
    const float column = static_cast<float>(i % 3), row = static_cast<float>(i / 3),
                shade = 0.07f * static_cast<float>(i);
    s.objects.push_back(sceneObject("cube-" + std::to_string(i), makeCube(0.28f),
                                    translate(id, {1.0f + column, 0.28f - kSunk, -2.6f + row}),
                                    {0.35f + shade, 0.5f, 0.85f - shade}));
  }
  s.objects.push_back(sceneObject("sphere", makeSphere(0.7f, slices, std::max(2, slices / 2)),
                                  translate(id, {-0.4f, 1.3f, 1.2f}), {0.85f, 0.35f, 0.3f}));
  if (moving) {
    SceneObject torus = sceneObject("torus", makeTorus(0.5f, 0.16f, 32, 12),
                                    translate(id, {2.0f, 2.1f, -1.6f}), {0.9f, 0.75f, 0.3f});
    torus.spinAxis = glm::normalize(glm::vec3(1, 0, 0.4f));
    torus.spinDegPerSecond = 25.0f;
    torus.bob = 0.3f;
    s.objects.push_back(torus);
    SceneObject spinner =
        sceneObject("spinner", makeCube(0.3f), translate(id, {-1.2f, 2.6f, -1.4f}), {0.5f, 0.8f, 0.55f});
    spinner.spinAxis = glm::normalize(glm::vec3(1, 1, 0));
    spinner.spinDegPerSecond = 40.0f;
    s.objects.push_back(spinner);
  }
  if (many) {  // a ring of dim lights: each adds little, the sum is what the eye sees
    for (int i = 0; i < kManyLights; ++i) {
      const float a = glm::two_pi<float>() * static_cast<float>(i) / kManyLights;
      const glm::vec3 hue = 0.5f + 0.5f * glm::vec3(std::cos(a), std::cos(a + 2.1f), std::cos(a + 4.2f));
      s.lights.push_back({glm::vec4(4.0f * std::cos(a), 3.5f, 4.0f * std::sin(a), 1.0f), 0.06f * hue, 9.0f});
    }
  } else {
    s.lights.push_back({{-2.0f, 4.6f, 2.4f, 1.0f}, {1.0f, 0.78f, 0.55f}, 10.0f});    // warm, above the sphere
    s.lights.push_back({{3.2f, 3.2f, -0.4f, 1.0f}, {0.45f, 0.6f, 1.0f}, 5.5f});      // blue, over the cubes
    s.lights.push_back({{-3.0f, 2.8f, -2.6f, 1.0f}, {0.5f, 1.0f, 0.55f}, 4.5f});     // green, small bounds
    s.lights.push_back({{0.4f, 1.0f, 0.5f, 0.0f}, {0.3f, 0.3f, 0.32f}, kInfinity});  // directional
  }
  return s;
}

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "16-fast-robust-shadows";
  info.title = "Fast, practical and robust shadows";
  info.summary =
      "McGuire et al.'s shadow-volume system: doubled vertices extruded on the GPU, z-pass or z-fail per\n"
      "caster from the occlusion pyramid, dark caps as fans, light bounds, many lights in a float target.";
  info.options = {
      {"method", 'M',
       "0 McGuire et al. (per caster: case 1 z-pass, 2 and 3 z-fail), 1 Everitt-Kilgard (always z-fail,\n"
       "      full caps), 2 Lengyel (z-pass unless a caster is in the pyramid, then full z-fail), 3 z-pass "
       "only",
       0, 3},
      {"light", 'L', "the light drawn last, whose stencil the frame ends with (the one --oracle checks)", 0,
       kManyLights - 1},
      {"many", 'N', "thirty-two dim point lights in a ring instead of the scene's four", 0},
      {"float", 'F', "accumulate light in an RGBA16F target (off: RGBA8, which bands)", 1},
      {"slices", 'Y', "the sphere's slices (stacks: half as many)", 24, 256, 4},
      {"light-cap", 'C', "draw the light cap of case-3 casters", 1},
      {"split", 'G', "split dark-cap fan triangles that span 180 degrees or more", 1},
      {"bounds", 'B', "cull casters and scissor by the light's bounds", 1},
      {"moving", 'O', "the moving casters (a torus and a cube above the grid)", 1},
      {"show", 'X', "overlay: casters coloured by case, their volumes and silhouettes", 0},
      {"fill", 'I',
       "measure: each light's volumes drawn again without the depth test, in a pass of their own\n"
       "      (volume-fill), whose fragments are every fragment the volumes rasterize",
       0},
      {"shadow", 'H', "shadows at all (off: every light reaches everything)", 1},
      {"mark", 'U',
       "after counting, mark the casters' sides turned from the light shadowed (float depth path only;\n"
       "      off: the count alone)",
       1},
      {"ambient", 'A',
       "the built-in scene's ambient light, in hundredths (a scene file brings its own); the views\n"
       "      from the sphere's shadow raise it, the warm light being behind the sphere there",
       12, 100},
      {"tint", 'W',
       "overlay: the pixels the light drawn last leaves in shadow (stencil not 0) tinted blue, so a\n"
       "      wrong count shows in the picture",
       0},
      {"stretch", 'K',
       "overlay: a contrast stretch, the light sum doubled this many times before it is shown, so\n"
       "      8-bit rounding's bands show",
       0, 3},
      {"silhouettes", 'E',
       "how a closed caster's possible silhouette edges are found, built once per caster and queried\n"
       "      per light, the same edges each way: 0 brute force (every edge of the mesh's adjacency), 1\n"
       "      streaming (a SilhouetteCaster's facing and edge passes), 2 dual space (a tree of face\n"
       "      planes the light's plane cuts, DualSilhouettes); an open caster always takes 0",
       0, 2},
  };
  info.camera.target = {-0.2f, 0.6f, 0.0f};
  info.camera.distance = 10.5f;
  info.camera.azimuthDeg = 25.0f;
  info.camera.elevationDeg = 32.0f;
  info.camera.farPlane = kInfinity;
  const std::pair<std::string, int> lit = {"ambient", kShadowAmbient}, tint = {"tint", 1};
  info.variants = {
      {"system", "the whole system: four lights, every caster by its case", {}},
      {"case-colours",
       "casters coloured by their case (green 1, amber 2, red 3, grey culled), volumes and silhouettes",
       {{"show", 1}}},
      {"directional",
       "the directional light drawn last: every volume converges to one point",
       {{"light", 3}}},
      {"eye-in-shadow",
       "the eye in the sphere's shadow, looking away: the sphere in case 2",
       {},
       {},
       eyeInShadow()},
      {"looking-up",
       "the eye in the sphere's shadow, looking up past it: the sphere in case 3, its shadow tinted",
       {lit, tint},
       {},
       lookingUp()},
      {"looking-up-colours", "the same with the overlay", {lit, {"show", 1}}, {}, lookingUp()},
      {"everitt-kilgard", "always z-fail with full caps", {{"method", 1}, lit, tint}, {}, lookingUp()},
      {"lengyel",
       "z-pass when no caster is in the pyramid, else full z-fail",
       {{"method", 2}, lit, tint},
       {},
       lookingUp()},
      {"zpass-only",
       "z-pass for every caster with the eye in a shadow: the count is wrong",
       {{"method", 3}, {"mark", 0}},
       {},
       eyeInShadow()},
      {"no-light-cap",
       "the case-3 sphere without its light cap: the count is wrong, the tint shows where",
       {{"light-cap", 0}, {"mark", 0}, lit, tint},
       {},
       lookingUp()},
      {"no-bounds", "no culling or scissor: the same shadows, more work", {{"bounds", 0}}},
      {"many-lights",
       "thirty-two dim lights accumulated in RGBA16F, shown contrast-stretched fourfold",
       {{"many", 1}, {"stretch", 2}}},
      {"many-lights-8bit",
       "the same accumulated in RGBA8: each light rounded, bands (stretched fourfold)",
       {{"many", 1}, {"float", 0}, {"stretch", 2}}},
      {"pinf-fixed24",
       "the whole system on the old path: a 24-bit fixed-point depth buffer with GL's depth mapping (Pinf)",
       {},
       {},
       {},
       false},
  };
  info.reversedDepth = true;  // a float depth buffer, reversed, where the driver has clip control
  info.sceneLightOption = "light";
  info.shadows = true;
  info.passes = {"ambient", "shadows", "volume-fill", "illumination", "overlay"};
  return info;
}

// ---- the overlays --------------------------------------------------------------------------------

// The light sum doubled `times` times in the accumulation target, which is bound: a rectangle
// over the window blended as destination * 1 + destination. Levels 8 bits would round to
// 1/255 apart come out 2^times levels apart once shown, where the eye can tell them.
void stretchContrast(const Program& flat, const WindowRectangle& window, int times) {
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_CULL_FACE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_DST_COLOR, GL_ONE);
  flat.set("transform", glm::mat4(1.0f));  // the rectangle is in clip space already
  flat.set("colour", glm::vec4(1.0f));
  for (int i = 0; i < times; ++i) window.draw();
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

// Where the stencil the frame ends with is not 0 (the light drawn last is blocked), a blue
// tint: a count that goes wrong shows as tint where the picture should have none, or none
// where it should. Tests the stencil, writes only colour.
void tintShadow(const Program& flat, const WindowRectangle& window) {
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_STENCIL_TEST);
  glStencilMask(0x00);
  glStencilFunc(GL_NOTEQUAL, 0, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  flat.set("transform", glm::mat4(1.0f));
  flat.set("colour", glm::vec4(0.2f, 0.45f, 1.0f, 0.35f));
  window.draw();
  glDisable(GL_BLEND);
  glStencilMask(0xFF);
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_DEPTH_TEST);
}

// ---- the case overlay ----------------------------------------------------------------------------

// The casters coloured by their case for the light drawn last (grey culled, green 1, amber 2,
// red 3), their volumes translucent in the same colour, their silhouettes as lines.
void FastRobustShadows::drawOverlay(const Frame& f) {
  const glm::vec4 caseColour[4] = {{0.5f, 0.5f, 0.5f, 0.55f},
                                   {0.2f, 0.85f, 0.3f, 0.55f},
                                   {1.0f, 0.7f, 0.1f, 0.55f},
                                   {1.0f, 0.15f, 0.1f, 0.55f}};
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(depth_.lequal);
  glDepthMask(GL_FALSE);  // the overlay changes no depth (and, stencil test off, no stencil)
  glEnable(GL_POLYGON_OFFSET_FILL);
  // The tint lies on the caster, drawn by another shader: pulled towards the eye, which is
  // towards smaller depths in GL's mapping and larger ones reversed.
  const float towardsEye = f.reversedDepth ? 1.0f : -1.0f;
  glPolygonOffset(towardsEye, towardsEye);
  for (const Caster& c : casters_) {
    flat_.set("transform", depth_.projection * f.view * meshes_.models()[c.object]);
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
    glDepthFunc(depth_.lequal);
  }
  glDisable(GL_BLEND);
  glDepthFunc(depth_.less);
  glDepthMask(GL_TRUE);
}

// ---- the counts --stats reports, the volume-fill measure, the oracle's claim ----------------------

// The counts --stats reports in every frame, whatever happens in it (volume_pieces, count_groups
// and the dual_* counts only in frames that have them).
void FastRobustShadows::startCounts(Frame& f) {
  for (const char* name :
       {"lights_drawn", "lights_offscreen", "casters_culled", "casters_case1", "casters_case2",
        "casters_case3", "casters_zfail", "side_triangles", "dark_cap_triangles", "light_cap_triangles",
        "split_fan_triangles", "fan_spheres", "depth_bounds_used", "depth_bounds_skipped",
        "objects_cut_by_near_plane", "rooms", "lights_buried", "mark_triangles"})
    f.count(name, 0);
}

// What one caster cost the light being drawn: skipped (case 0, culled by the light's bounds; or
// a room), or its case, its silhouette query and its volumes, lightVolumes_ from `first` on.
void FastRobustShadows::recordCaster(Frame& f, const Caster& c, int shadowCase, bool room,
                                     std::size_t first) const {
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
void FastRobustShadows::recordLastLight(Frame& f) const {
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
void FastRobustShadows::drawVolumeFill(const Frame& f, const glm::vec4& light) {
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glDisable(GL_DEPTH_TEST);  // in front of the scene or behind, every fragment is fill
  glDisable(GL_CULL_FACE);
  for (const LightVolume& lv : lightVolumes_) {
    const CasterVolume& v = lv.volume;
    setExtrusion(f, casters_[lv.caster], light);
    casters_[lv.caster].gpu->draw(lv.first, v.sides + v.darkCap + v.lightCap);
    if (lv.first == 0) casters_[lv.caster].gpu->drawSplit();
  }
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
}

std::optional<ShadowCheck> FastRobustShadows::shadowCheck(const Frame& f) const {
  if (!f.on("shadow") || scene_.lights.empty()) return std::nullopt;
  const SceneLight& light = scene_.lights[static_cast<std::size_t>(lightOrder(f).back())];
  ShadowCheck check{{}, light.position, [](std::uint8_t s) { return s == 0; }, true};
  if (f.on("bounds")) check.lightRadius = light.radius;
  for (const SceneObject& o : scene_.objects)
    check.objects.push_back({&o.mesh, o.modelAt(f.time), o.casts, o.receives});
  return check;
}

}  // namespace stencil::fast_robust_shadows
