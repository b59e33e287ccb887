// Lesson 16: fast, practical and robust shadow volumes (McGuire, Hughes, Egan, Kilgard and
// Everitt, "Fast, Practical and Robust Shadows", 2003).
//
// Lessons 07-09 counted volume faces in front of the scene (z-pass), which breaks when the eye,
// or the near plane, lies in a shadow. Counting the faces behind the scene instead (z-fail)
// never meets the near plane, but needs the volume closed at both ends, caps that cost a
// triangle per caster face. The paper's system pays only where it must:
//   - every caster keeps a doubled vertex array (each vertex with w = 1 and w = 0); a vertex
//     shader sends the w = 0 copies to infinity away from the light, so a volume is indices only;
//   - the possible silhouette (edges between a face towards and a face away from the light) is
//     found in object space and extruded into side quads that face out of the volume;
//   - the occlusion pyramid, from the light to the camera's near rectangle, holds every caster
//     whose volume can reach the eye: outside it (case 1) z-pass with the sides alone; inside it
//     z-fail with the sides and the dark cap (a fan over the silhouette at infinity), plus the
//     light cap (the caster's lit faces) only when the caster may be on screen (case 3, not 2);
//   - each point light has finite bounds: casters that miss them are culled, and the light's
//     shadow and illumination passes are scissored to their rectangle on screen, and its
//     volumes depth-bounded where the driver has EXT_depth_bounds_test;
//   - scene files may bring open meshes, whose faces block light from both sides (a volume from
//     each side), and lights inside a caster's hull, where the fan comes out a whole sphere off
//     and gets it back (closeAroundLight);
//   - the rendering system of its section 8: an ambient pass fills the depth buffer, then per
//     light, the stencil cleared, its shadow volumes counted, and the light added with stencil
//     EQUAL 0 and additive blending, into a float target so many lights do not band.
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

#include "geometry/bounds.h"
#include "geometry/dual_silhouette.h"
#include "geometry/fast_shadows.h"
#include "geometry/projection.h"
#include "geometry/scene.h"
#include "geometry/shadow_volume.h"
#include "geometry/shapes.h"
#include "gl/doubled_caster.h"
#include "gl/errors.h"
#include "gl/framebuffer.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/recorder.h"
#include "gl/shader.h"

using namespace stencil;

namespace {

constexpr int kManyLights = 32;
// The ambient light, in hundredths, of the views from inside the sphere's shadow: there the warm
// light is behind the sphere, and at the scene's 0.12 most of the picture is near black.
constexpr int kShadowAmbient = 40;

// An orbit camera placed at `eye`, looking at `target`.
OrbitCamera lookingFrom(glm::vec3 eye, glm::vec3 target, float fovyDeg) {
  OrbitCamera c;
  const glm::vec3 back = eye - target;
  c.target = target;
  c.distance = glm::length(back);
  c.elevationDeg = glm::degrees(std::asin(back.y / c.distance));
  c.azimuthDeg = glm::degrees(std::atan2(back.x, back.z));
  c.fovyDeg = fovyDeg;
  c.farPlane = kInfinity;
  return c;
}

// Where the eye sits in the sphere's shadow from the warm light: on the line from the light
// through the sphere's centre, past the sphere, a little above the ground.
glm::vec3 underTheSphere() {
  const glm::vec3 light(-2.0f, 4.6f, 2.4f), sphere(-0.4f, 1.3f, 1.2f);
  return light + 1.3f * (sphere - light);
}

// The eye in that shadow looking away from the light, over the cubes: the near plane lies in
// the sphere's volume, so z-pass alone fails; the sphere is in the occlusion pyramid but out of
// view (case 2).
OrbitCamera eyeInShadow() {
  return lookingFrom(underTheSphere(), {2.0f, 0.3f, -1.6f}, 70.0f);
}

// Half a unit aside in the same shadow, looking up past the sphere at the stairs: the sphere is
// in the pyramid and on screen (case 3), its light cap needed.
OrbitCamera lookingUp() {
  return lookingFrom(underTheSphere() + glm::vec3(0.5f, 0.0f, 0.0f), {-2.5f, 1.6f, 0.9f}, 70.0f);
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
       {{"ambient", kShadowAmbient}, {"tint", 1}},
       {},
       lookingUp()},
      {"looking-up-colours",
       "the same with the overlay",
       {{"ambient", kShadowAmbient}, {"show", 1}},
       {},
       lookingUp()},
      {"everitt-kilgard",
       "always z-fail with full caps",
       {{"method", 1}, {"ambient", kShadowAmbient}, {"tint", 1}},
       {},
       lookingUp()},
      {"lengyel",
       "z-pass when no caster is in the pyramid, else full z-fail",
       {{"method", 2}, {"ambient", kShadowAmbient}, {"tint", 1}},
       {},
       lookingUp()},
      {"zpass-only",
       "z-pass for every caster with the eye in a shadow: the count is wrong",
       {{"method", 3}},
       {},
       eyeInShadow()},
      {"no-light-cap",
       "the case-3 sphere without its light cap: the count is wrong, the tint shows where",
       {{"light-cap", 0}, {"ambient", kShadowAmbient}, {"tint", 1}},
       {},
       lookingUp()},
      {"no-bounds", "no culling or scissor: the same shadows, more work", {{"bounds", 0}}},
      {"many-lights",
       "thirty-two dim lights accumulated in RGBA16F, shown contrast-stretched fourfold",
       {{"many", 1}, {"stretch", 2}}},
      {"many-lights-8bit",
       "the same accumulated in RGBA8: each light rounded, bands (stretched fourfold)",
       {{"many", 1}, {"float", 0}, {"stretch", 2}}},
  };
  info.variants.push_back({"pinf-fixed24",
                           "the whole system on the old path: a 24-bit fixed-point depth buffer with GL's "
                           "depth mapping (Pinf)",
                           {},
                           {},
                           {},
                           false});
  info.reversedDepth = true;  // a float depth buffer, reversed, where the driver has clip control
  info.sceneLightOption = "light";
  info.shadows = true;
  info.passes = {"ambient", "shadows", "volume-fill", "illumination", "overlay"};
  return info;
}

// ---- the scene ------------------------------------------------------------------------------

// Objects on the ground stand a little into it: a silhouette edge lying in the ground's plane
// would extrude into a side face coplanar with the ground there, whose depth test is a toss-up.
constexpr float kSunk = 0.01f;

// In the spirit of the paper's figures: stairs, a grid of cubes, a sphere, two moving casters,
// coloured attenuated point lights with finite bounds and one directional light.
Scene builtInScene(int slices, bool many, bool moving) {
  using glm::translate;
  const glm::mat4 id(1.0f);
  Scene s;
  s.ambient = glm::vec3(0.12f);
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

// The lesson's own framebuffer: a float (or 8-bit) colour target for the light sum and a packed
// depth/stencil buffer of the framework's format, so depth and stencil copy across unchanged (a
// depth/stencil blit needs identical formats).
class AccumulationTarget {
 public:
  AccumulationTarget(glm::ivec2 size, bool floating, DepthFormat depth)
      : size_(size), floating_(floating), depth_(depth) {
    glGenFramebuffers(1, &fbo_);
    glGenRenderbuffers(2, renderbuffers_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, floating ? GL_RGBA16F : GL_RGBA8, size.x, size.y);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers_[0]);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, depthStencilFormat(depth), size.x, size.y);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              renderbuffers_[1]);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("the accumulation framebuffer is incomplete");
  }
  ~AccumulationTarget() {
    glDeleteFramebuffers(1, &fbo_);
    glDeleteRenderbuffers(2, renderbuffers_);
  }
  AccumulationTarget(const AccumulationTarget&) = delete;
  AccumulationTarget& operator=(const AccumulationTarget&) = delete;

  bool fits(glm::ivec2 size, bool floating, DepthFormat depth) const {
    return size == size_ && floating == floating_ && depth == depth_;
  }
  void bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glViewport(0, 0, size_.x, size_.y);
  }
  // Colour (clamped to 0..1 by the copy), depth and stencil into the framework's framebuffer,
  // where the pass snapshots, the stencil pictures and the oracle read them.
  void copyTo(GLuint framebuffer) const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    glBlitFramebuffer(0, 0, size_.x, size_.y, 0, 0, size_.x, size_.y,
                      GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, GL_NEAREST);
  }

 private:
  glm::ivec2 size_;
  bool floating_;
  DepthFormat depth_;
  GLuint fbo_ = 0, renderbuffers_[2] = {0, 0};
};

// ---- the lesson ---------------------------------------------------------------------------------

class FastRobustShadows final : public Lesson {
 public:
  explicit FastRobustShadows(const Scene* fromFile)
      : light_("common/light.vert", "common/light.frag"),
        extrude_("common/extrude.vert", "common/flat.frag"),
        flat_("common/flat.vert", "common/flat.frag") {
    if (fromFile) setScene(*fromFile);
    window_.upload(
        {{-1, -1, 0, 1}, {1, -1, 0, 1}, {1, 1, 0, 1}, {-1, -1, 0, 1}, {1, 1, 0, 1}, {-1, 1, 0, 1}});
  }

  void render(Frame& f) override {
    prepare(f);
    // The counts --stats reports, present in every frame whatever happens in it.
    for (const char* name :
         {"lights_drawn", "lights_offscreen", "casters_culled", "casters_case1", "casters_case2",
          "casters_case3", "casters_zfail", "side_triangles", "dark_cap_triangles", "light_cap_triangles",
          "split_fan_triangles", "fan_spheres", "depth_bounds_used", "depth_bounds_skipped",
          "objects_cut_by_near_plane", "rooms", "lights_buried"})
      f.count(name, 0);
    for (Caster& c : casters_) c.volume = {};
    GLint framework = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framework);
    framework_ = static_cast<GLuint>(framework);
    // The depth mapping before anything is cleared or drawn. Reversed (Frame::reversedDepth): window
    // depth is clip z / w with no remapping, 1 at the near plane and n/d at distance d, which the
    // float depth buffer holds to about 2^-24 of d at every distance. The framework's framebuffer
    // has the matching depth format.
    setDepthMapping(f);
    const DepthFormat depthFormat = f.reversedDepth ? DepthFormat::Float32 : DepthFormat::Fixed24;
    if (!target_ || !target_->fits(f.size, f.on("float"), depthFormat))
      target_ = std::make_unique<AccumulationTarget>(f.size, f.on("float"), depthFormat);
    target_->bind();
    // Frustum planes, the near rectangle and the light's bounds read GL's convention, not the
    // reversed matrix the frame draws with.
    const glm::mat4 viewProjection = f.projection * f.view;
    // A mirrored view turns every triangle round on screen: what faces the eye winds clockwise.
    glFrontFace(glm::determinant(f.view) < 0.0f ? GL_CW : GL_CCW);

    // ---- ambient: the depth buffer filled once, for every light ------------------------------
    glClearColor(0.02f, 0.025f, 0.035f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);  // depth: the farthest
    glEnable(GL_DEPTH_TEST);                                                     // the nearest surface wins
    glDepthFunc(less_);
    markCutByNearPlane(f, viewProjection);
    // Rooms: a closed caster around the eye is a shell seen from inside (geometry/solid.h).
    models_.clear();
    for (const SceneObject& o : scene_.objects) models_.push_back(o.modelAt(f.time));
    solids_ = solidsSeenFrom(scene_, models_, f.eye);
    if (!solids_.refusal.empty()) throw UsageError(solids_.refusal);
    glEnable(GL_CULL_FACE);  // a closed object's back faces are hidden, unless the near plane cuts it
    const glm::vec3 ambient =
        fromFile_ ? scene_.ambient : glm::vec3(0.01f * static_cast<float>(f.option("ambient")));
    drawScene(f, glm::vec4(0, 1, 0, 0), glm::vec3(0), kInfinity, ambient);
    endPass(f, "ambient");

    // ---- per light: its shadow in the stencil, then its light where the stencil is 0 --------
    const std::vector<int> order = lightOrder(f);
    const std::array<glm::vec3, 4> nearRect = nearRectangle(viewProjection);
    const Frustum frustum = viewFrustum(viewProjection, false);
    for (std::size_t k = 0; k < order.size(); ++k) {
      const SceneLight& light = scene_.lights[static_cast<std::size_t>(order[k])];
      const bool checked = k + 1 == order.size();
      const std::string which = "light " + std::to_string(order[k]);  // the passes say whose they are
      const LightClip clip =
          lightClip(light.position, light.radius, f.on("bounds"), f.view, f.projection, f.size);
      if (clip.offScreen()) {  // its bounds are off screen: it adds nothing
        f.count("lights_offscreen");
        continue;
      }
      f.count("lights_drawn");
      glScissor(clip.scissor.x, clip.scissor.y, clip.scissor.width, clip.scissor.height);

      // The stencil cleared everywhere, so what the frame ends with is this light's alone.
      glStencilMask(0xFF);
      glClear(GL_STENCIL_BUFFER_BIT);
      if (f.on("shadow") && lightBuried(scene_, models_, solids_, light.position)) {
        // A light inside a solid (outside the room the eye is in) lights nothing the eye sees:
        // its picture is all shadow, a count of 1 everywhere, and it adds no light.
        glClearStencil(1);
        glClear(GL_STENCIL_BUFFER_BIT);
        glClearStencil(0);
        f.count("lights_buried");
        endPass(f, "shadows", which);
        f.shadowMask("light-" + std::to_string(order[k]));
        target_->bind();  // reading the mask may have bound another framebuffer
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
      if (f.on("shadow")) drawShadows(f, light, clip, nearRect, frustum, checked);
      if (depthBounds) glDisable(GL_DEPTH_BOUNDS_TEST_EXT);
      endPass(f, "shadows", which);
      f.shadowMask("light-" + std::to_string(order[k]));
      target_->bind();                       // reading the mask may have bound another framebuffer
      if (f.on("fill") && f.on("shadow")) {  // the fill the stencil test saw, for --stats
        drawVolumeFill();
        endPass(f, "volume-fill", which);
      }

      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);  // the light's colour is added
      glDepthMask(GL_FALSE);                            // onto the surfaces already there
      glDepthFunc(GL_EQUAL);                            // exactly the ambient pass's surfaces
      glEnable(GL_STENCIL_TEST);
      glStencilFunc(GL_EQUAL, 0, 0xFF);        // outside every volume
      glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);  // the count stays for the next look
      glEnable(GL_BLEND);
      glBlendFunc(GL_ONE, GL_ONE);                                             // light adds up
      drawScene(f, light.position, light.colour, light.radius, glm::vec3(0));  // its own fall-off
      glDisable(GL_BLEND);
      glDisable(GL_STENCIL_TEST);
      glDisable(GL_SCISSOR_TEST);
      glDepthFunc(less_);
      glDepthMask(GL_TRUE);
      endPass(f, "illumination", which);
    }

    // Per caster, for the light drawn last: its case (0 culled) and what its volume cost.
    for (const Caster& c : casters_) {
      const std::string& name = scene_.objects[c.object].name;
      f.count("case." + name, static_cast<std::uint64_t>(c.volume.shadowCase));
      f.count("sides." + name, c.volume.sides / 3);
      f.count("dark_cap." + name, c.volume.darkCap / 3 + c.volume.splitVertices / 3);
      f.count("light_cap." + name, c.volume.lightCap / 3);
    }

    // ---- the classroom's view: cases, volumes, silhouettes of the light drawn last ------------
    if (f.option("stretch") > 0) {  // in the accumulation target, before RGBA16F is clamped to 8 bits
      stretchContrast(f.option("stretch"));
      target_->copyTo(framework_);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framework_);
    if (f.on("tint")) tintShadow();
    if (f.on("show")) drawOverlay(f);
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);  // GL's default again
    f.pass("overlay");
  }

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
  struct Caster {
    std::size_t object;
    BoundingSphere bounds;  // object space
    std::unique_ptr<DoubledCaster> gpu;
    CasterVolume volume;  // for the light drawn last
    bool convex = false;  // a convex caster's volume nests once
    // Built on first use (--set silhouettes=1 or 2) and kept with the caster; the tree reads
    // the prepared caster, so both live behind pointers that do not move.
    std::unique_ptr<SilhouetteCaster> streaming;
    std::unique_ptr<DualSilhouettes> dual;
  };

  // The possible silhouette edges of a closed caster for a light in its space, found the way
  // --set silhouettes says; nothing for 0 (casterVolume's brute force) or an open caster.
  const std::vector<SilhouetteEdge>* silhouetteOf(Frame& f, Caster& caster, const glm::vec4& local) {
    const PreparedCaster& prepared = scene_.objects[caster.object].caster;
    const int how = f.option("silhouettes");
    if (how == 0 || !prepared.report.closedManifold()) return nullptr;
    if (!caster.streaming)
      caster.streaming =
          std::make_unique<SilhouetteCaster>(prepareSilhouettes(prepared.mesh, prepared.adjacency));
    if (how == 1) {
      facesLight(*caster.streaming, local, facing_);
      possibleSilhouetteEdges(*caster.streaming, facing_, edges_);
    } else {
      if (!caster.dual) caster.dual = std::make_unique<DualSilhouettes>(*caster.streaming);
      caster.dual->query(local, edges_);
      f.count("dual_cells_visited", caster.dual->lastQuery().cellsVisited);
      f.count("dual_edges_tested", caster.dual->lastQuery().edgesTested);
    }
    return &edges_;
  }

  void setScene(const Scene& scene) {
    scene_ = scene;
    fromFile_ = !scene.file.empty();
    drawn_.clear();
    closed_.clear();
    objectBounds_.clear();
    casters_.clear();
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
      SceneObject& o = scene_.objects[i];
      drawn_.push_back(std::make_unique<GpuMesh>(o.mesh));
      objectBounds_.push_back(boundingSphereOf(o.mesh.positions));
      if (!o.casts) {
        closed_.push_back(prepareCaster(o.mesh).report.closedManifold());
        continue;
      }
      if (o.caster.mesh.positions.empty()) o.caster = prepareCaster(o.mesh);
      closed_.push_back(o.caster.report.closedManifold());
      casters_.push_back({i,
                          boundingSphereOf(o.caster.mesh.positions),
                          std::make_unique<DoubledCaster>(o.caster.mesh),
                          {},
                          isConvex(o.caster.mesh, o.caster.adjacency),
                          nullptr,
                          nullptr});
    }
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

  void endPass(Frame& f, const char* name, const std::string& detail = {}) {
    target_->copyTo(framework_);
    f.pass(name, detail);
    target_->bind();  // the recorder binds the framework's framebuffer after each pass
  }

  // ---- the shadow volumes of one light ------------------------------------------------------

  void drawShadows(Frame& f, const SceneLight& light, const LightClip& clip,
                   const std::array<glm::vec3, 4>& nearRect, const Frustum& frustum, bool checked) {
    fillTime_ = f.time;
    fillLight_ = light.position;
    // Everything that decides each caster's volume first (Lengyel's choice needs all of them).
    std::vector<BoundingSphere> world;
    for (const Caster& c : casters_)
      world.push_back(worldBounds(c.bounds, scene_.objects[c.object].modelAt(f.time)));
    const std::vector<VolumeChoice> choices =
        chooseVolumes(static_cast<ShadowMethod>(f.option("method")), world, clip.centre, clip.radius,
                      occlusionPyramid(nearRect, light.position), frustum);

    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // only the stencil changes
    glDepthMask(GL_FALSE);                                // volumes are not surfaces
    glDepthFunc(less_);                                   // in front of the scene: pass; behind: fail
    glDisable(GL_CULL_FACE);                              // both faces in one draw, two-sided stencil
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);  // every volume fragment counts
    lightVolumes_.clear();
    for (std::size_t c = 0; c < casters_.size(); ++c) {
      Caster& caster = casters_[c];
      const SceneObject& o = scene_.objects[caster.object];
      if (choices[c].shadowCase == 0) {
        f.count("casters_culled");
        if (checked) caster.volume = {};
        continue;
      }
      if (solids_.room[caster.object]) {  // convex (solidsSeenFrom checks): nothing inside it is
        f.count("rooms");                 // in its shadow, and its volume would hold infinity
        if (checked) caster.volume = {};
        continue;
      }
      f.count("casters_case" + std::to_string(choices[c].shadowCase));
      const glm::vec4 local = glm::inverse(o.modelAt(f.time)) * light.position;  // in the caster's space
      buildVolume(f, c, local, choices[c], checked);
    }

    // Count every volume; where their counts could add past 255 (an 8-bit count would wrap to 0,
    // lit), in groups that cannot pass 127, each folded into bit 7 (geometry/shadow_volume.h).
    std::vector<std::size_t> nesting;
    for (const LightVolume& lv : lightVolumes_) nesting.push_back(lv.nesting);
    const CountPlan plan = countPlan(nesting);
    for (int g = 0; g < plan.groups; ++g) {
      if (plan.fold) glStencilMask(0x7F);  // bit 7 keeps what the groups before found
      for (std::size_t k = 0; k < lightVolumes_.size(); ++k)
        if (plan.group[k] == g) countVolume(f, lightVolumes_[k], light.position);
      if (plan.fold) foldCount();
    }
    glStencilMask(0xFF);
    if (plan.fold) f.count("count_groups", static_cast<std::uint64_t>(plan.groups));
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_CULL_FACE);  // the scene's own culling again
  }

  // One volume counted for the current light: a caster's whole volume, or one piece of it.
  struct LightVolume {
    std::size_t caster;
    std::size_t first;  // into the caster's uploaded indices
    CasterVolume volume;
    std::size_t nesting;  // the most it can add to a pixel's count
  };

  // One caster's volume for this light, uploaded and listed in lightVolumes_: as the method
  // chose it, or, where it could nest deeper than a count group's 127, in pieces of its light
  // cap, each a full-caps z-fail volume (Everitt and Kilgard's caps close any piece).
  void buildVolume(Frame& f, std::size_t c, const glm::vec4& local, const VolumeChoice& choice,
                   bool checked) {
    Caster& caster = casters_[c];
    const PreparedCaster& prepared = scene_.objects[caster.object].caster;
    VolumeIndices built = casterVolume(prepared, local, choice, f.on("light-cap"), f.on("split"), nullptr,
                                       silhouetteOf(f, caster, local));
    const CasterVolume& v = built.volume;
    const bool closed = prepared.report.closedManifold();
    const bool outside = local.w == 0.0f || glm::distance(glm::vec3(local) / local.w, caster.bounds.centre) >
                                                caster.bounds.radius;
    std::size_t nesting = 1;
    if (!caster.convex) {
      std::size_t lit = 0;
      for (bool l : facesLight(prepared.mesh, local)) lit += l;
      // An open caster casts from both sides, and a fold of it changes the count by two.
      nesting = closed ? nestingBound(lit, v.silhouette / 2, false, outside)
                       : nestingBound(prepared.mesh.indices.size() / 3, v.silhouette, false, outside);
    }
    std::vector<LightVolume> volumes{{c, 0, v, nesting}};
    if (nesting > 127 && closed) {
      volumes.clear();
      std::vector<std::uint32_t> indices;
      const VolumeChoice full{choice.shadowCase, true, true};
      for (const std::vector<bool>& piece : litFacePieces(facesLight(prepared.mesh, local), 127)) {
        const VolumeIndices p = casterVolume(prepared, local, full, true, false, &piece);
        std::size_t pieceLit = 0;
        for (bool l : piece) pieceLit += l;
        volumes.push_back({c, indices.size(), p.volume, pieceLit});
        indices.insert(indices.end(), p.indices.begin(), p.indices.end());
      }
      built = {volumes.empty() ? CasterVolume{} : volumes.front().volume, indices, {}};
      f.count("volume_pieces", volumes.size());
    }
    caster.gpu->upload(built.indices, built.split);
    for (const LightVolume& lv : volumes) {
      const CasterVolume& pv = lv.volume;
      if (pv.zfail) f.count("casters_zfail");
      f.count("side_triangles", pv.sides / 3);
      f.count("dark_cap_triangles", pv.darkCap / 3 + pv.splitVertices / 3);
      f.count("light_cap_triangles", pv.lightCap / 3);
      f.count("split_fan_triangles", pv.splitTriangles);
      f.count("fan_spheres", static_cast<std::uint64_t>(pv.spheres));
      lightVolumes_.push_back(lv);
    }
    if (checked) caster.volume = volumes.front().volume;
  }

  // One volume counted: z-pass in front of the scene, or z-fail behind it.
  void countVolume(const Frame& f, const LightVolume& lv, const glm::vec4& worldLight) {
    const Caster& caster = casters_[lv.caster];
    const glm::mat4 model = scene_.objects[caster.object].modelAt(f.time);
    const CasterVolume& v = lv.volume;
    extrude_.set("viewProjection", projection_ * f.view);
    extrude_.set("model", model);
    extrude_.set("light", glm::inverse(model) * worldLight);
    if (!v.zfail) {  // z-pass: count the faces in front of the scene
      glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);  // the eye ray enters a volume
      glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);   // and leaves it
      caster.gpu->draw(lv.first, v.sides);
    } else {  // z-fail: count the faces behind the scene, the volume closed at both ends
      glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);   // behind: the ray leaves a volume
      glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);  // behind: it enters one
      caster.gpu->draw(lv.first,
                       v.sides + v.darkCap);  // the dark cap at infinity fails LESS (GREATER) by itself
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

  // The light's volumes once more, every fragment passing: nothing written, only counted by the
  // pass's occlusion query. The same geometry and scissor as the shadows pass.
  void drawVolumeFill() {
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glDisable(GL_DEPTH_TEST);  // in front of the scene or behind, every fragment is fill
    glDisable(GL_CULL_FACE);
    for (const LightVolume& lv : lightVolumes_) {
      const SceneObject& o = scene_.objects[casters_[lv.caster].object];
      const CasterVolume& v = lv.volume;
      extrude_.set("model", o.modelAt(fillTime_));
      extrude_.set("light", glm::inverse(o.modelAt(fillTime_)) * fillLight_);
      casters_[lv.caster].gpu->draw(lv.first, v.sides + v.darkCap + v.lightCap);
      if (lv.first == 0) casters_[lv.caster].gpu->drawSplit();
    }
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
  }

  // ---- the scene -----------------------------------------------------------------------------

  void drawScene(const Frame& f, glm::vec4 light, glm::vec3 colour, float radius, glm::vec3 ambient) {
    light_.set("viewProjection", projection_ * f.view);
    light_.set("ambient", ambient);
    light_.set("light", light);
    light_.set("lightColour", colour);
    light_.set("radius", std::isinf(radius) ? 1e30f : radius);
    light_.set("twoSided", 1);  // a wall seen from inside a room is lit on the side the eye sees
    light_.set("eye", f.eye);
    light_.set("shininess", 32.0f);
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
      const SceneObject& o = scene_.objects[i];
      light_.set("model", o.modelAt(f.time));
      light_.set("colour", o.colour);
      if (closed_[i] && !cutByNearPlane_[i])
        glEnable(GL_CULL_FACE);  // a closed object's back faces are hidden anyway
      else  // an open surface is seen from both sides; a cut one shows its inside through the cut
        glDisable(GL_CULL_FACE);
      drawn_[i]->draw();
    }
    glEnable(GL_CULL_FACE);
  }

  // Back-face culling hides the inside of a closed object only while the object is whole on
  // screen: where the near plane cuts it, the eye looks through the cut at its back faces, and
  // culling them would show what lies behind the object instead. Only such objects pay for
  // their back faces.
  void markCutByNearPlane(Frame& f, const glm::mat4& viewProjection) {
    const Plane nearPlane = viewFrustum(viewProjection, false).planes[4];
    const float length = glm::length(glm::vec3(nearPlane));
    cutByNearPlane_.assign(scene_.objects.size(), false);
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
      const BoundingSphere world = worldBounds(objectBounds_[i], scene_.objects[i].modelAt(f.time));
      cutByNearPlane_[i] =
          (glm::dot(glm::vec3(nearPlane), world.centre) + nearPlane.w) / length < world.radius;
      f.count("objects_cut_by_near_plane", cutByNearPlane_[i] && closed_[i] ? 1 : 0);
    }
  }

  // The light sum doubled `times` times in the accumulation target, which is bound: a rectangle
  // over the window blended as destination * 1 + destination. Levels 8 bits would round to
  // 1/255 apart come out 2^times levels apart once shown, where the eye can tell them.
  void stretchContrast(int times) {
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_DST_COLOR, GL_ONE);
    flat_.set("transform", glm::mat4(1.0f));  // the rectangle is in clip space already
    flat_.set("colour", glm::vec4(1.0f));
    for (int i = 0; i < times; ++i) window_.draw();
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
  }

  // Where the stencil the frame ends with is not 0 (the light drawn last is blocked), a blue
  // tint: a count that goes wrong shows as tint where the picture should have none, or none
  // where it should. Tests the stencil, writes only colour.
  void tintShadow() {
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0x00);
    glStencilFunc(GL_NOTEQUAL, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    flat_.set("transform", glm::mat4(1.0f));
    flat_.set("colour", glm::vec4(0.2f, 0.45f, 1.0f, 0.35f));
    window_.draw();
    glDisable(GL_BLEND);
    glStencilMask(0xFF);
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
  }

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
      const SceneObject& o = scene_.objects[c.object];
      flat_.set("transform", projection_ * f.view * o.modelAt(f.time));
      flat_.set("colour", caseColour[c.volume.shadowCase]);
      drawn_[c.object]->draw();
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_CULL_FACE);  // both sides of the volumes show
    const SceneLight& light = scene_.lights[static_cast<std::size_t>(lightOrder(f).back())];
    for (const Caster& c : casters_) {
      if (c.volume.shadowCase == 0) continue;
      const glm::mat4 model = scene_.objects[c.object].modelAt(f.time);
      extrude_.set("viewProjection", projection_ * f.view);
      extrude_.set("model", model);
      extrude_.set("light", glm::inverse(model) * light.position);
      glm::vec4 colour = caseColour[c.volume.shadowCase];
      colour.a = 0.12f;
      extrude_.set("colour", colour);
      c.gpu->draw(0, c.volume.sides + c.volume.darkCap + c.volume.lightCap);
      c.gpu->drawSplit();
      extrude_.set("colour", glm::vec4(1.0f, 1.0f, 0.6f, 1.0f));
      glDepthFunc(GL_ALWAYS);  // the silhouettes show through their casters
      c.gpu->draw(c.volume.sides + c.volume.darkCap + c.volume.lightCap, c.volume.silhouette, GL_LINES);
      glDepthFunc(lequal_);
    }
    glDisable(GL_BLEND);
    glDepthFunc(less_);
    glDepthMask(GL_TRUE);
  }

  Program light_, extrude_, flat_;
  GLenum less_ = GL_LESS, lequal_ = GL_LEQUAL;  // the depth tests of this frame's depth mapping
  glm::mat4 projection_{1.0f};                  // what the frame draws with: f.projection, maybe reversed
  Scene scene_;
  bool fromFile_ = false;
  int sceneKey_ = -1;
  std::vector<std::unique_ptr<GpuMesh>> drawn_;
  std::vector<bool> closed_;                  // per object: a closed mesh, drawn with back faces culled
  std::vector<BoundingSphere> objectBounds_;  // per object, object space
  std::vector<glm::mat4> models_;             // per object, this frame
  SolidsSeen solids_;                         // this frame's rooms
  std::vector<bool> cutByNearPlane_;          // per object, this frame: back faces drawn
  std::vector<Caster> casters_;
  std::vector<LightVolume> lightVolumes_;  // the current light's
  std::vector<std::uint8_t> facing_;       // silhouetteOf's facing flags and edges, reused
  std::vector<SilhouetteEdge> edges_;
  GpuTriangles window_;    // the whole window, for folding the count
  double fillTime_ = 0.0;  // and what drawVolumeFill needs
  glm::vec4 fillLight_{0.0f};
  std::unique_ptr<AccumulationTarget> target_;
  GLuint framework_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  return runSceneLesson(
      lessonInfo(), [](const Scene* fromFile) { return std::make_unique<FastRobustShadows>(fromFile); }, argc,
      argv);
}
