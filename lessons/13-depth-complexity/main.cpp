// Lesson 13: depth complexity (Kilgard, "Improving Shadows and Reflections via the Stencil
// Buffer", section 7 and figure 20, the GLUT demo dinodraw.c; the SIGGRAPH '97 course demo
// complexity.c).
//
// How many fragments land on each pixel? Draw the scene once more with colour writes off, the
// stencil test ALWAYS passing and INCR as the operation on what is to be counted:
//   every fragment     the depth test off (or INCR on both of its outcomes);
//   depth-pass         INCR where the depth test passes: the fragments that were written;
//   depth-fail         INCR where it fails: the fragments drawn for nothing, hidden already.
// The first is the depth complexity proper (how many surfaces the pixel's ray crosses), the
// other two split it by the order the scene was drawn in, so passed + failed = all. With back
// faces culled, only the front faces count.
//
// The stencil then holds a count per pixel, and a picture of it is a full-screen quad per count k
// drawn where the stencil is EQUAL k, in k's colour: a ramp that grows brighter with the count.
// An occlusion query around each of those quads says how many pixels have count k, the histogram
// of the picture, and a few queries with stencil LESS find the largest count first.
//
// The stencil has 8 bits: INCR stops at 255 and INCR_WRAP starts again at 0. A count of 255
// after INCR means "255 or more", shown in a colour of its own off the ramp; a wrapped count is
// silently wrong, which the 300-quad stack shows.
//
// The same count measures shadow volumes' fill (the `volumes` option): instead of the scene, each
// light's shadow volumes, built as lesson 16 builds them for one of its methods (McGuire et al.,
// Everitt-Kilgard, Lengyel, z-pass; geometry/fast_shadows.h and gl/doubled_caster.h), drawn with
// INCR on both depth outcomes, under the light's scissor and depth bounds as that lesson draws
// them. The count is then the fragments the stencil pass rasterizes per pixel, all lights
// together: where McGuire et al.'s culling, per-case caps and bounds save fill, and how much.

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "geometry/depth_complexity.h"
#include "geometry/fast_shadows.h"
#include "geometry/scene.h"
#include "geometry/shapes.h"
#include "gl/doubled_caster.h"
#include "gl/framebuffer.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/light_shading.h"
#include "gl/overlay.h"
#include "gl/shader.h"
#include "gl/stencil_view.h"

using namespace stencil;

namespace {

constexpr int kStackLayers = 300;  // more than an 8-bit stencil counts

// What the count pass counts (the "count" option).
constexpr int kEveryFragment = 0, kDepthPass = 1, kDepthFail = 2, kBothOutcomes = 3;

class DepthComplexity final : public Lesson {
 public:
  explicit DepthComplexity(const Scene* fromFile)
      : light_("common/light.vert", "common/light.frag"),
        flat_("common/flat.vert", "common/flat.frag"),
        extrude_("common/extrude.vert", "common/flat.frag"),
        quadMesh_(makeScreenQuad()),
        quad_(quadMesh_) {
    scene_ = fromFile ? *fromFile : builtInScene();
    stack_ = stackScene();
    for (const Scene* s : {&scene_, &stack_})
      for (const SceneObject& o : s->objects) gpu_[&o.mesh] = std::make_unique<GpuMesh>(o.mesh);
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {  // the casters, as lesson 16 keeps them
      SceneObject& o = scene_.objects[i];
      if (!o.casts) continue;
      if (o.caster.mesh.positions.empty()) o.caster = prepareCaster(o.mesh);
      casters_.push_back(
          {i, boundingSphereOf(o.caster.mesh.positions), std::make_unique<DoubledCaster>(o.caster.mesh)});
    }
  }

  void render(Frame& f) override {
    const Scene& scene = f.on("stack") ? stack_ : scene_;
    // A mirrored view turns every triangle round on screen: what faces the eye winds clockwise.
    glFrontFace(glm::determinant(f.view) < 0.0f ? GL_CW : GL_CCW);
    if (f.on("cull")) {
      glEnable(GL_CULL_FACE);  // only the faces towards the eye are drawn, so only they count
      glCullFace(GL_BACK);
    } else {
      glDisable(GL_CULL_FACE);  // both sides of every surface are drawn and counted
    }

    // 1. The frame as it would be: the shaded scene, nearest surface wins.
    glClearColor(0.1f, 0.1f, 0.13f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);  // the nearest surface wins
    glDepthFunc(GL_LESS);
    glDisable(GL_STENCIL_TEST);  // the stencil is not used yet
    drawShaded(f, scene);
    f.pass("scene");

    // 2. Count: the scene once more, into the stencil only. Shadow volumes are counted against the
    // scene's depth, as the shadow pass meets it; the scene's own surfaces against an empty one.
    const bool countVolumes = f.on("volumes") && !f.on("stack");
    if (!countVolumes)
      glClear(GL_DEPTH_BUFFER_BIT);  // the depth test sees the scene arrive in draw order again
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // counting shows nothing yet
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);                // all 8 bits count
    glStencilFunc(GL_ALWAYS, 0, 0xFF);  // every fragment reaches the stencil operation
    const GLenum up = f.on("wrap") ? GL_INCR_WRAP : GL_INCR;
    switch (f.option("count")) {
      case kEveryFragment:
        glDisable(GL_DEPTH_TEST);           // no depth test: every fragment takes the pass path
        glStencilOp(GL_KEEP, GL_KEEP, up);  // and counts
        break;
      case kDepthPass:
        glStencilOp(GL_KEEP, GL_KEEP, up);  // nearer than all drawn before it: written
        break;
      case kDepthFail:
        glStencilOp(GL_KEEP, up, GL_KEEP);  // behind something drawn before it: hidden
        break;
      case kBothOutcomes:
        glStencilOp(GL_KEEP, up, up);  // either way: every fragment, with the depth test on
        break;
    }
    if (countVolumes) {
      drawVolumes(f, up);
    } else {
      glDepthMask(
          GL_TRUE);  // as in the scene's draw: with the depth test on, later fragments meet earlier ones
      drawFlat(f, scene);
    }
    f.pass("count");

    // 3. The histogram: pixels per count, by occlusion queries on full-screen quads.
    glDisable(GL_DEPTH_TEST);                // the quads cover every pixel whatever lies there
    glDisable(GL_CULL_FACE);                 // a quad counts its pixels whichever way it faces
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);  // the counts stay as they are
    const bool saturates = !f.on("wrap");
    std::vector<std::uint64_t> histogram(256, 0);
    f.ownOcclusionQueries([&] {  // the browser's queries are boolean: there the stencil is read
      histogram = f.features.samplesPassed ? measureHistogram() : stencilHistogram(f.framebuffer(), f.size);
    });
    int top = 1, largest = 0;
    std::uint64_t counted = 0, covered = 0;
    for (int k = 1; k < 256; ++k) {
      const std::uint64_t n = histogram[static_cast<std::size_t>(k)];
      if (n == 0) continue;
      largest = k;
      if (!(saturates && k == 255)) top = k;
      counted += n * static_cast<std::uint64_t>(k);
      covered += n;
    }
    f.pass("histogram");

    // 4. Show: each count's pixels in its colour, a full-screen quad where the stencil EQUALs it.
    if (f.on("show")) {
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);  // the picture replaces the scene
      for (int k = 0; k <= largest; ++k) {
        if (histogram[static_cast<std::size_t>(k)] == 0) continue;
        glStencilFunc(GL_EQUAL, k, 0xFF);  // exactly the pixels with count k
        const auto c = saturates && k == 255 ? saturatedCountColour() : countColour(k, top);
        drawQuad(glm::vec4(c[0], c[1], c[2], 255.0f) / 255.0f);
      }
    }
    glDisable(GL_STENCIL_TEST);                       // the counts stay for --stencil-out and the tests
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);  // colour writes on again
    glEnable(GL_DEPTH_TEST);                          // the depth test as the frame began it
    f.pass("show");

    // 5. The legend along the bottom: the ramp, the histogram as bars, and 255+ where INCR stops.
    if (f.on("legend") && f.on("show")) {
      // Its digits grow with the window's UI scale (1 headless: the pictures the goldens hold).
      const int textScale = static_cast<int>(std::lround((f.size.x >= 480 ? 2 : 1) * f.uiScale));
      const Image legend = countLegend(histogram, top, saturates, f.size.x, textScale);
      overlay_.draw(legend, 0, f.size.y - legend.height, f.size.y);
    }
    f.pass("legend");
    glDisable(GL_CULL_FACE);  // GL's defaults again
    glFrontFace(GL_CCW);

    report(f, histogram, largest, counted, covered);
    if (f.on("oracle") && !f.on("volumes")) checkAgainstRayCount(f, scene);
  }

 private:
  // ---- the histogram --------------------------------------------------------------------------

  // Pixels per stencil value, 256 entries. First the largest value present, by bisection: with
  // stencil LESS a quad passes where ref < stencil, so a query says whether any count exceeds ref.
  // Then one query per value up to it, the quad passing where the stencil EQUALs the value.
  std::vector<std::uint64_t> measureHistogram() {
    GLuint queries[256];
    glGenQueries(256, queries);
    const auto samples = [&](GLenum func, int ref, GLuint query) {
      glStencilFunc(func, ref, 0xFF);  // the quad passes where `ref func stencil` holds
      glBeginQuery(GL_SAMPLES_PASSED, query);
      drawQuad(glm::vec4(0.0f));
      glEndQuery(GL_SAMPLES_PASSED);
    };
    const auto result = [](GLuint query) {
      GLuint64 n = 0;
      glGetQueryObjectui64v(query, GL_QUERY_RESULT, &n);
      return static_cast<std::uint64_t>(n);
    };
    int low = 0, high = 255;  // the largest value lies in [low, high]
    while (low < high) {
      const int middle = (low + high) / 2;
      samples(GL_LESS, middle, queries[0]);
      if (result(queries[0]) > 0)
        low = middle + 1;  // some count exceeds middle
      else
        high = middle;
    }
    for (int k = 0; k <= low; ++k) samples(GL_EQUAL, k, queries[k]);
    std::vector<std::uint64_t> histogram(256, 0);
    for (int k = 0; k <= low; ++k) histogram[static_cast<std::size_t>(k)] = result(queries[k]);
    glDeleteQueries(256, queries);
    return histogram;
  }

  // ---- drawing --------------------------------------------------------------------------------

  void drawShaded(const Frame& f, const Scene& scene) {
    const SceneLight light =
        scene.lights.empty() ? SceneLight{{3.0f, 6.0f, 4.0f, 1.0f}} : scene.lights.front();
    setLightShading(light_, {.viewProjection = f.projection * f.view,
                             .eye = f.eye,
                             .light = light.position,
                             .lightColour = light.colour,
                             .ambient = scene.ambient + glm::vec3(0.15f),
                             .shininess = 24.0f});
    for (const SceneObject& o : scene.objects) {
      light_.set("model", o.modelAt(f.time));
      light_.set("colour", o.colour);
      frontFaceFor(f, o.modelAt(f.time));
      gpu_.at(&o.mesh)->draw();
    }
    frontFaceFor(f, glm::mat4(1.0f));
  }

  // The counted draw: the same triangles in the same order, nothing shaded (no colour is written).
  void drawFlat(const Frame& f, const Scene& scene) {
    flat_.set("colour", glm::vec4(1.0f));
    for (const SceneObject& o : scene.objects) {
      flat_.set("transform", f.projection * f.view * o.modelAt(f.time));
      frontFaceFor(f, o.modelAt(f.time));
      gpu_.at(&o.mesh)->draw();
    }
    frontFaceFor(f, glm::mat4(1.0f));
  }

  // A mirrored view or a mirroring model (a negative determinant, scale -1 1 1) turns a triangle
  // round on screen: what faces the eye then winds clockwise. Both together cancel.
  static void frontFaceFor(const Frame& f, const glm::mat4& model) {
    const bool mirrored = (glm::determinant(glm::mat3(f.view)) < 0.0f) != (glm::determinant(glm::mat3(model)) < 0.0f);
    glFrontFace(mirrored ? GL_CW : GL_CCW);
  }

  // Every light's shadow volumes as lesson 16 draws them for the chosen method, every fragment
  // counted: INCR on both depth outcomes, so the depth test (on, the scene's depth kept) discards
  // nothing, and the count is what the stencil pass rasterizes. The scene's depth stays for the
  // depth bounds test.
  void drawVolumes(Frame& f, GLenum up) {
    const auto method = static_cast<ShadowMethod>(f.option("volumes") - 1);
    for (const char* name : {"lights_drawn", "lights_offscreen", "casters_culled", "casters_zfail",
                             "volume_triangles", "depth_bounds_used"})
      f.count(name, 0);
    glEnable(GL_DEPTH_TEST);       // on, as the stencil pass has it; both outcomes count
    glDepthFunc(GL_LESS);          // lesson 16's test: in front of the scene passes
    glDepthMask(GL_FALSE);         // volumes are not surfaces
    glDisable(GL_CULL_FACE);       // both faces of every volume are rasterized
    glStencilOp(GL_KEEP, up, up);  // every fragment that reaches the stencil counts
    const glm::mat4 viewProjection = f.projection * f.view;
    const std::array<glm::vec3, 4> nearRect = nearRectangle(viewProjection);
    const Frustum frustum = viewFrustum(viewProjection, false);
    std::vector<BoundingSphere> world;
    for (const Caster& c : casters_)
      world.push_back(worldBounds(c.bounds, scene_.objects[c.object].modelAt(f.time)));
    extrude_.set("viewProjection", viewProjection);
    extrude_.set("colour", glm::vec4(1.0f));
    for (const SceneLight& light : scene_.lights) {
      const LightClip clip =
          lightClip(light.position, light.radius, f.on("bounds"), f.view, f.projection, f.size);
      if (clip.offScreen()) {  // lesson 16 skips a light whose bounds are off screen
        f.count("lights_offscreen");
        continue;
      }
      f.count("lights_drawn");
      glEnable(GL_SCISSOR_TEST);  // only the light's rectangle, as the method's stencil pass
      glScissor(clip.scissor.x, clip.scissor.y, clip.scissor.width,
                clip.scissor.height);  // the light's sphere on screen (the whole window unbounded)
      const bool depthBounds = hasFeature(f.features, Feature::DepthBoundsTest) && clip.depthBounds;
      if (depthBounds) {  // pixels whose surface lies outside the light's sphere are skipped
        glEnable(GL_DEPTH_BOUNDS_TEST_EXT);  // as lesson 16 does, where the driver has it
        glDepthBoundsEXT(clip.depth.nearest, clip.depth.farthest);  // the depths the sphere spans
        f.count("depth_bounds_used");
      }
      const std::vector<int> cases =
          shadowCases(world, clip, occlusionPyramid(nearRect, light.position), frustum);
      const bool inPyramid = anyInPyramid(cases);
      for (std::size_t c = 0; c < casters_.size(); ++c) {
        if (cases[c] == 0) {
          f.count("casters_culled");
          continue;
        }
        const SceneObject& o = scene_.objects[casters_[c].object];
        const glm::mat4 model = o.modelAt(f.time);
        const glm::vec4 local = glm::inverse(model) * light.position;  // the light in the caster's space
        const std::vector<bool> lit = facesLight(o.caster.mesh, local);
        const VolumeIndices built =
            volumeOf(o.caster, local, recipeFor(method, cases[c], inPyramid, true, local.w == 0.0f), lit,
                     possibleSilhouetteEdges(o.caster, lit));
        const CasterVolume& v = built.volume;
        if (v.zfail) f.count("casters_zfail");
        f.count("volume_triangles", (v.sides + v.darkCap + v.lightCap + v.splitVertices) / 3);
        casters_[c].gpu->upload(built.indices, built.split);
        extrude_.set("model", model);
        extrude_.set("light", local);
        casters_[c].gpu->draw(0, v.sides + v.darkCap + v.lightCap);
        casters_[c].gpu->drawSplit();
      }
      if (depthBounds) glDisable(GL_DEPTH_BOUNDS_TEST_EXT);  // the next light has bounds of its own
      glDisable(GL_SCISSOR_TEST);  // the next light's rectangle, or the whole window again
    }
    glDepthMask(GL_TRUE);  // GL's default again
  }

  void drawQuad(const glm::vec4& colour) {
    flat_.set("transform", glm::mat4(1.0f));
    flat_.set("colour", colour);
    quad_.draw();
  }

  // ---- the scenes -----------------------------------------------------------------------------

  // Surfaces behind surfaces: three cubes nested in each other (six crossings through the middle),
  // a row of spheres along the line of sight, three linked tori turning, on an open ground.
  static Scene builtInScene() {
    using glm::translate;
    const glm::mat4 id(1.0f);
    Scene s;
    s.ambient = glm::vec3(0.1f);
    s.lights.push_back({{3.0f, 6.0f, 4.0f, 1.0f}, glm::vec3(1.0f)});
    s.objects.push_back(sceneObject("ground", makePlane(4.0f, 1), id, {0.7f, 0.7f, 0.66f}, false));
    const float sizes[3] = {0.8f, 0.55f, 0.3f};
    for (int i = 0; i < 3; ++i)
      s.objects.push_back(sceneObject("cube-" + std::to_string(i), makeCube(sizes[i]),
                                      glm::rotate(translate(id, {-1.7f, 0.85f, -0.2f}), 0.5f, {0, 1, 0}),
                                      {0.9f - 0.2f * static_cast<float>(i), 0.45f, 0.2f}));
    for (int i = 0; i < 4; ++i)
      s.objects.push_back(sceneObject(
          "sphere-" + std::to_string(i), makeSphere(0.45f, 24, 12),
          translate(id, {0.5f - 0.45f * static_cast<float>(i), 0.5f, 1.6f - 1.1f * static_cast<float>(i)}),
          {0.3f, 0.6f + 0.08f * static_cast<float>(i), 0.4f}));
    for (int i = 0; i < 3; ++i) {
      SceneObject torus =
          sceneObject("torus-" + std::to_string(i), makeTorus(0.5f, 0.14f, 32, 12),
                      glm::rotate(translate(id, {1.5f + 0.55f * static_cast<float>(i), 1.1f, -0.4f}),
                                  glm::radians(90.0f) * static_cast<float>(i % 2), {1, 0, 0}),
                      {0.85f, 0.75f - 0.15f * static_cast<float>(i), 0.3f});
      torus.spinAxis = {1.0f, 0.0f, 0.0f};
      torus.spinDegPerSecond = 20.0f;
      s.objects.push_back(torus);
    }
    return s;
  }

  // kStackLayers quads one behind the other along the line of sight, each facing the eye; the
  // farther ones look smaller, so the count falls from kStackLayers in the middle to 1 at the rim.
  static Scene stackScene() {
    Mesh quads;
    const glm::vec3 normal(0.0f, 0.0f, 1.0f);
    for (int i = 0; i < kStackLayers; ++i) {
      const float z = -0.02f * static_cast<float>(i);
      const auto first = static_cast<std::uint32_t>(quads.positions.size());
      for (const glm::vec2 corner :
           {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        quads.positions.push_back({corner, z});
        quads.normals.push_back(normal);
      }
      quads.indices.insert(quads.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
    }
    Scene s;
    s.lights.push_back({{0.0f, 2.0f, 5.0f, 1.0f}, glm::vec3(1.0f)});
    s.objects.push_back(sceneObject("stack", quads, glm::mat4(1.0f), {0.8f, 0.8f, 0.8f}, false));
    return s;
  }

  // A shadow caster of the scene: its object, bounds in its own space, doubled vertices on the GPU.
  struct Caster {
    std::size_t object;
    BoundingSphere bounds;
    std::unique_ptr<DoubledCaster> gpu;
  };

  Program light_, flat_, extrude_;
  Mesh quadMesh_;
  GpuMesh quad_;
  Scene scene_, stack_;
  std::map<const Mesh*, std::unique_ptr<GpuMesh>> gpu_;
  ImageOverlay overlay_;
  std::vector<Caster> casters_;

  // ---- test hooks: what --stats reports, and the oracle -----------------------------------------

  static void report(Frame& f, const std::vector<std::uint64_t>& histogram, int largest,
                     std::uint64_t counted, std::uint64_t covered) {
    f.count("max_count", static_cast<std::uint64_t>(largest));
    f.count("covered_pixels", covered);     // count 1 or more
    f.count("counted_fragments", counted);  // the sum of the counts: fragments counted, as stored
    f.count("saturated_pixels", f.on("wrap") ? 0 : histogram[255]);  // INCR stopped there
    for (int k = 0; k <= largest; ++k)
      if (histogram[static_cast<std::size_t>(k)] > 0)
        f.count("histogram." + std::to_string(k), histogram[static_cast<std::size_t>(k)]);
  }

  // The stencil against the surfaces each pixel centre's ray crosses (geometry/depth_complexity.h),
  // saturated or wrapped as the stencil operation does; pixels on an edge of the ray count's
  // picture are forgiven. Only every fragment is a property of the scene: depth-pass and
  // depth-fail depend on the order it is drawn in.
  void checkAgainstRayCount(Frame& f, const Scene& scene) const {
    const int count = f.option("count");
    if (count != kEveryFragment && count != kBothOutcomes) return;
    std::vector<OracleObject> objects;
    for (const SceneObject& o : scene.objects) objects.push_back({&o.mesh, o.modelAt(f.time), false, false});
    const std::vector<std::uint32_t> crossings = depthComplexity(
        objects, f.projection * f.view, f.size, f.on("cull") ? FacesCounted::Front : FacesCounted::All);
    std::vector<std::uint8_t> rows(static_cast<std::size_t>(f.size.x) * static_cast<std::size_t>(f.size.y));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, f.size.x, f.size.y, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, rows.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    std::vector<std::uint32_t> expected(crossings.size()), stencil(crossings.size());
    const std::size_t w = static_cast<std::size_t>(f.size.x);
    for (std::size_t i = 0; i < crossings.size(); ++i) {
      const std::size_t y = i / w, x = i % w;  // GL's rows bottom up, the ray count's top down
      stencil[i] = rows[(static_cast<std::size_t>(f.size.y) - 1 - y) * w + x];
      expected[i] = f.on("wrap") ? crossings[i] % 256 : std::min<std::uint32_t>(crossings[i], 255);
    }
    const CountReport r = compareCounts(expected, stencil, f.size);
    f.count("oracle_pixels", r.pixels);
    f.count("oracle_disagreements", r.disagreements);
    f.count("oracle_on_edges", r.onEdges);
    f.count("oracle_expected_fragments", r.expectedTotal);
    if (r.disagreements != r.onEdges)
      f.checkFailed("oracle: " + std::to_string(r.disagreements - r.onEdges) +
                    " pixels off the edges hold another count than the ray count");
  }
};

// ---- the lesson: options, variants, cameras ------------------------------------------------------

// Straight down the stack of quads (stackScene), from 4 units in front of the nearest.
OrbitCamera alongTheStack() {
  return {.target = {0.0f, 0.0f, -3.0f},
          .distance = 7.0f,
          .azimuthDeg = 0.0f,
          .elevationDeg = 0.0f,
          .farPlane = 40.0f};
}

// For the volumes' fill: the eye low in the nested cubes' shadow, looking past them at the spheres
// and tori, so casters lie between the light and the near plane (cases 2 and 3) and the methods
// differ; the far plane at infinity, where the volumes' far ends lie.
OrbitCamera inTheCubesShadow() {
  const glm::vec3 light(3.0f, 6.0f, 4.0f), cubeTop(-1.7f, 1.65f, -0.2f);
  OrbitCamera c = orbitCameraFrom(light + 1.287f * (cubeTop - light), {0.6f, 0.6f, 0.6f});
  c.fovyDeg = 70.0f;
  c.farPlane = std::numeric_limits<float>::infinity();
  return c;
}

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "13-depth-complexity";
  info.title = "Depth complexity";
  info.summary =
      "The scene drawn once more into the stencil only, INCR on every fragment, on those that pass the\n"
      "depth test or on those that fail it; the counts in pseudo-colour with a histogram from occlusion "
      "queries.";
  info.options = {
      {"count", 'C',
       "what is counted: 0 every fragment (depth test off), 1 fragments that pass the depth test,\n"
       "      2 fragments that fail it, 3 every fragment by INCR on both depth outcomes",
       kEveryFragment, 3},
      {"cull", 'U', "cull back faces: only front faces are drawn, and counted", 0},
      {"show", 'X', "the counts in pseudo-colour (off: the shaded scene; the stencil counts all the same)",
       1},
      {"legend", 'L', "the legend: a column per count, its bar the share of pixels with that count", 1},
      {"wrap", 'W', "INCR_WRAP, which starts again at 0 after 255 (off: INCR, which stops at 255)", 0},
      {"stack", 'T', "a stack of 300 quads face on instead of the objects: counts past 255", 0},
      {"volumes", 'F',
       "count the shadow volumes' fill instead of the scene: every fragment of every light's volumes,\n"
       "      built as lesson 16's method builds them: 0 off, 1 McGuire et al., 2 Everitt-Kilgard,\n"
       "      3 Lengyel, 4 z-pass",
       0, 4},
      {"bounds", 'B', "volumes: the lights' bounds cull casters, scissor and depth-bound their volumes", 1},
      {"oracle", 'K',
       "check the stencil against a CPU count of the surfaces each pixel's ray crosses\n"
       "      (every fragment only; --stats reports oracle_*)",
       0},
  };
  info.variants = {
      {"all", "every fragment counted, both sides of every surface", {}},
      {"all-culled", "every fragment of the front faces: back faces culled", {{"cull", 1}}},
      {"depth-pass",
       "the fragments that pass the depth test: what was written, in draw order",
       {{"count", kDepthPass}}},
      {"depth-fail", "the fragments that fail the depth test: drawn for nothing", {{"count", kDepthFail}}},
      {"both-outcomes",
       "INCR on both depth outcomes, depth test on: the same as every fragment",
       {{"count", kBothOutcomes}}},
      {"shaded", "the scene the counts are of, shaded", {{"show", 0}}},
      {"stack-saturates",
       "300 quads, INCR: the count stops at 255, shown as 255+",
       {{"stack", 1}},
       {},
       alongTheStack()},
      {"stack-wraps",
       "300 quads, INCR_WRAP: 300 wraps to 44, silently wrong",
       {{"stack", 1}, {"wrap", 1}},
       {},
       alongTheStack()},
      {"fill-mcguire",
       "the shadow volumes' fill, McGuire et al.: per caster z-pass sides, or z-fail with a fan cap",
       {{"volumes", 1}},
       {},
       inTheCubesShadow()},
      {"fill-everitt-kilgard",
       "the shadow volumes' fill, Everitt-Kilgard: every volume closed by both caps",
       {{"volumes", 2}},
       {},
       inTheCubesShadow()},
      {"fill-lengyel",
       "the shadow volumes' fill, Lengyel: z-pass unless a caster is in the pyramid",
       {{"volumes", 3}},
       {},
       inTheCubesShadow()},
      {"fill-zpass",
       "the shadow volumes' fill, z-pass: the sides alone",
       {{"volumes", 4}},
       {},
       inTheCubesShadow()},
  };
  info.passes = {"scene", "count", "histogram", "show", "legend"};
  info.camera.target = {0.0f, 0.7f, 0.0f};
  info.camera.distance = 7.5f;
  info.camera.azimuthDeg = 20.0f;
  info.camera.elevationDeg = 22.0f;
  info.camera.farPlane = 40.0f;
  return info;
}

}  // namespace

int main(int argc, char** argv) {
  return runSceneLesson(
      lessonInfo(), [](const Scene* fromFile) { return std::make_unique<DepthComplexity>(fromFile); }, argc,
      argv);
}
