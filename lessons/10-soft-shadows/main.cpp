// Lesson 10: soft shadows from a cluster of point lights (Kilgard, "Improving Shadows and
// Reflections via the Stencil Buffer", section 6.4 and figure 15, after Brotman and Badler 1984).
//
// An area light casts a penumbra: a receiver point there sees part of the light. Sample the light
// with N point lights, give each a hard shadow volume, and add each light at 1/N intensity where
// it is not shadowed: a point that k of the N lights reach gets k/N of the light, an estimate of
// the fraction of the area light it sees.
//
// Kilgard's recipe (the variant kilgard-8), eight lights, one stencil bit each:
//   1. the scene with ambient light only, filling the depth buffer;
//   2. per light i, its shadow volumes with stencil write mask 1 << i, INVERT where the depth
//      test passes (z-pass parity, lesson 07), colour and depth writes off;
//   3. per light i, the scene again at 1/8 of the light, added (blend ONE, ONE), only on the
//      ambient pass's surfaces (depth EQUAL), where bit i is 0 -- and bit i set where the light
//      is added, so a second surface at the same depth (a coplanar mat here) cannot add it again.
// Its limits, each a variant: N lights give N + 1 levels (banding); INVERT is parity, so the
// overlap of two casters' volumes is lit; eight bits hold eight lights, so more need a stencil
// clear per eight; an 8-bit colour buffer rounds each 1/N term.
//
// The default corrects them: per light a robust z-fail count (closed volumes, lesson 15) in the
// whole stencil, the light added where the count is 0, into a float target; any N.
//
// Penumbra wedges (the variant wedges; Assarsson and Akenine-Moller 2003): only the penumbra needs
// N lights. Around every edge that is a silhouette edge from some point of the light, a convex
// wedge (the edge and its extrusions away from the light's corners) bounds the region where the
// lights can disagree; the wedges mark their pixels in a stencil bit, the N-light loop runs only
// there, and outside one light's hard shadow decides, every light added at once where it is lit.

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <memory>
#include <string>

#include "geometry/shadow_volume.h"
#include "geometry/shapes.h"
#include "geometry/soft_shadow.h"
#include "geometry/soft_shadow_reference.h"
#include "gl/errors.h"
#include "gl/framebuffer.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/shader.h"

using namespace stencil;

namespace {

constexpr int kMaxLights = 1024;

LessonInfo lessonInfo();  // the options, variants and camera, after the lesson

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

// The scene's pieces, the penumbra wedges and a framebuffer copy, defined after the lesson.
AreaLight areaLight(const Frame& f);
glm::mat4 slabModel();
Mesh matFrom(const Mesh& ground);
void penumbraWedges(const PreparedCaster& caster, const AreaLight& area, float scale,
                    std::vector<glm::vec4>& out, std::vector<std::pair<GLint, GLsizei>>& ranges);
void blit(GLuint from, GLuint to, glm::ivec2 size, GLbitfield mask);

struct Object {
  const Mesh* mesh;
  const GpuMesh* gpu;
  glm::mat4 model;
  glm::vec3 colour;
  bool caster;
};

// ---- the lesson -------------------------------------------------------------------------------

class SoftShadows final : public Lesson {
 public:
  SoftShadows()
      : light_("common/light.vert", "common/light.frag"),
        flat_("common/flat.vert", "common/flat.frag"),
        volume_("common/volume.vert", "common/flat.frag"),
        resolve_("common/volume.vert", "10-soft-shadows/resolve.frag"),
        lights_("common/light.vert", "10-soft-shadows/lights.frag"),
        groundMesh_(makePlane(kGroundHalf, kGroundDivisions)),
        matMesh_(matFrom(groundMesh_)),
        slabMesh_(makeCube(0.5f)),
        ballMesh_(makeSphere(kBallRadius, 24, 12)),
        ground_(groundMesh_),
        mat_(matMesh_),
        slab_(slabMesh_),
        ball_(ballMesh_),
        slabEdges_(prepareCaster(transformed(slabMesh_, slabModel()))),
        ballEdges_(prepareCaster(transformed(ballMesh_, glm::translate(glm::mat4(1.0f), kBallCentre)))) {
    glGenTextures(1, &lightsTexture_);
  }
  ~SoftShadows() override { glDeleteTextures(1, &lightsTexture_); }
  SoftShadows(const SoftShadows&) = delete;
  SoftShadows& operator=(const SoftShadows&) = delete;

  void render(Frame& f) override {
    const int n = f.option("lights");
    const bool kilgard = f.option("method") == 1;
    if (f.on("reference") && f.option("size") == 0)
      throw UsageError("--set reference=1 needs a light of size 1 or more");
    if (f.on("reference") && !f.on("converged") && f.option("casters") != 1)
      throw UsageError("--set reference=1 needs casters=1 (the slab alone) unless converged is on");
    if (f.on("wedges") && (kilgard || f.on("reference")))
      throw UsageError("--set wedges=1 needs method=0 (counting) and reference=0");
    for (const char* name :
         {"lights", "rounds", "samples", "stencil_clears", "volume_triangles", "illumination_draws",
          "light_groups", "penumbra_width_x_milli", "penumbra_width_x_predicted_milli",
          "penumbra_width_z_milli", "penumbra_width_z_predicted_milli", "wedges", "wedge_triangles",
          "reference_rays_per_pixel"})
      f.count(name, 0);
    framework_ = f.framebuffer();
    size_ = f.size;
    const GLenum format = f.option("float") == 1   ? GL_RGBA32F
                          : f.option("float") == 2 ? GL_RGBA16F
                                                   : GL_RGBA8;
    if (!target_ || !target_->fits(f.size, format)) target_ = std::make_unique<Target>(f.size, format, true);
    if (!saved_ || !saved_->fits(f.size, GL_RGBA8)) saved_ = std::make_unique<Target>(f.size, GL_RGBA8, true);

    // Progressive refinement: the same options as the last frame make another round of samples.
    std::string key = std::to_string(f.size.x) + "x" + std::to_string(f.size.y);
    for (const Option& o : lessonInfo().options) key += "," + std::to_string(f.option(o.name));
    round_ = (f.on("progressive") && key == lastKey_) ? round_ + 1 : 0;
    lastKey_ = key;
    const AreaLight area = areaLight(f);
    samples_.clear();
    for (glm::vec2 u : unitSquareSamples(static_cast<SamplePattern>(f.option("pattern")), n, round_))
      samples_.push_back(glm::vec4(lightPoint(area, u), 1.0f));
    f.count("lights", static_cast<std::uint64_t>(n));
    f.count("rounds", static_cast<std::uint64_t>(round_ + 1));
    f.count("samples", static_cast<std::uint64_t>(n) * static_cast<std::uint64_t>(round_ + 1));
    checked_ = std::min(f.option("light"), n - 1);

    target_->bind();
    const std::vector<Object> scene = sceneOf(f);
    const glm::mat4 viewProjection = f.projection * f.view;

    // ---- 1. ambient: the depth buffer filled once, for every light ---------------------------
    glClearColor(0.02f, 0.025f, 0.035f, 0.0f);
    glClearStencil(0);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);  // the mat, drawn after the ground at equal depths, shows
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);  // alpha counts lights, from 0
    const bool visibility = f.on("visibility") || f.on("reference");
    drawScene(f, scene, glm::vec4(0, 1, 0, 0), glm::vec3(0.0f), visibility ? glm::vec3(0.0f) : kAmbient,
              false);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    endPass(f, "ambient");

    if (f.on("reference") && f.on("converged")) {
      drawConverged(f, scene, area, viewProjection);
    } else if (f.on("reference")) {
      drawReference(f, area, viewProjection);
    } else if (kilgard) {
      kilgardLights(f, scene);
    } else if (f.on("wedges")) {
      wedgeLights(f, scene, area);
    } else {
      countingLights(f, scene);
    }

    // ---- the frame's light onto the framework's picture ------------------------------------------
    const Target* picture = target_.get();
    if (f.on("progressive")) {  // the running average of every round: weight 1 / rounds for this one
      if (!average_ || !average_->fits(f.size, GL_RGBA32F))
        average_ = std::make_unique<Target>(f.size, GL_RGBA32F, false);
      average_->bind();
      glEnable(GL_BLEND);
      glBlendColor(0.0f, 0.0f, 0.0f, 1.0f / static_cast<float>(round_ + 1));
      glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
      drawPicture(*target_, n, false);
      glDisable(GL_BLEND);
      picture = average_.get();
    }
    measurePenumbra(f, *picture, area);
    glBindFramebuffer(GL_FRAMEBUFFER, framework_);
    glViewport(0, 0, f.size.x, f.size.y);
    drawPicture(*picture, n, f.on("penumbra"));
    // The stencil the frame ends with: the checked light's hard shadow (saved after its volumes).
    blit(saved_->fbo(), framework_, f.size, GL_STENCIL_BUFFER_BIT);
    glBindFramebuffer(GL_FRAMEBUFFER, framework_);
    if (f.on("wedges") && f.on("show-wedges")) {  // the wedges' bit, kept in the saved stencil
      glDisable(GL_DEPTH_TEST);
      glEnable(GL_STENCIL_TEST);
      glStencilFunc(GL_EQUAL, kWedgeBit, kWedgeBit);
      glStencilMask(0);
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      volume_.set("transform", glm::mat4(1.0f));
      volume_.set("colour", glm::vec4(0.1f, 0.85f, 0.95f, 0.5f));
      window_.draw();
      glDisable(GL_BLEND);
      glDisable(GL_STENCIL_TEST);
      glStencilMask(0xFF);
      glEnable(GL_DEPTH_TEST);
    }
    f.pass("resolve");
  }

 private:
  class Target;  // a colour texture with the framework's depth and stencil, defined below

  std::vector<Object> sceneOf(const Frame& f) const {
    std::vector<Object> scene;
    scene.push_back({&groundMesh_, &ground_, glm::mat4(1.0f), {0.75f, 0.74f, 0.7f}, false});
    if (f.on("mat")) scene.push_back({&matMesh_, &mat_, glm::mat4(1.0f), {0.75f, 0.4f, 0.3f}, false});
    if (f.option("casters") & 1)
      scene.push_back({&slabMesh_, &slab_, slabModel(), {0.35f, 0.55f, 0.85f}, true});
    if (f.option("casters") & 2)
      scene.push_back(
          {&ballMesh_, &ball_, glm::translate(glm::mat4(1.0f), kBallCentre), {0.4f, 0.75f, 0.4f}, true});
    return scene;
  }

  void endPass(Frame& f, const char* name) {
    blit(target_->fbo(), framework_, f.size,
         GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    f.pass(name);
    target_->bind();  // the blit left the framework's framebuffer bound
  }

  // The light's share: 1/N of it, or all of it without the scale.
  float share(const Frame& f) const {
    return f.on("scale") ? 1.0f / static_cast<float>(f.option("lights")) : 1.0f;
  }

  // ---- Kilgard: a stencil bit per light ----------------------------------------------------------

  void kilgardLights(Frame& f, const std::vector<Object>& scene) {
    const int n = f.option("lights");
    for (int group = 0; group * 8 < n; ++group) {
      const int first = group * 8, last = std::min(n, first + 8);
      f.count("light_groups");
      if (group == 0 || f.on("reclear")) {  // eight fresh bits
        glStencilMask(0xFF);
        glClear(GL_STENCIL_BUFFER_BIT);
        f.count("stencil_clears");
      }
      // 2. Each light's volumes invert its own bit wherever they lie in front of the scene.
      if (f.on("shadow")) {
        volumeState(f);
        glDepthFunc(GL_LESS);
        glStencilFunc(GL_ALWAYS, 0, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);  // depth pass: one more crossing, parity flips
        for (int i = first; i < last; ++i) {
          glStencilMask(f.on("bit-mask") ? 1u << (i % 8) : 0xFFu);  // light i's bit alone
          for (const PreparedCaster* c : casters(f))
            drawVolume(f, silhouetteVolume(*c, samples_[static_cast<std::size_t>(i)], kInfinity));
        }
        restoreState();
      }
      if (checked_ >= first && checked_ < last) saveStencil();
      if (group == 0) endPass(f, "volumes");
      // 3. Each light added at 1/N where its bit is 0, setting the bit as it adds.
      for (int i = first; i < last; ++i) {
        const GLuint bit = 1u << (i % 8);
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_EQUAL, 0, bit);  // light i's bit clear: outside its volumes
        glStencilMask(bit);
        glStencilOp(GL_KEEP, GL_KEEP, f.on("update-bit") ? GL_INVERT : GL_KEEP);  // 0 -> 1: added once
        illuminate(f, scene, samples_[static_cast<std::size_t>(i)]);
      }
      if (group == 0) endPass(f, "illumination");
    }
    if (n > 8) endPass(f, "other-lights");
    glStencilMask(0xFF);
  }

  // ---- the corrected system: a z-fail count per light -----------------------------------------

  void countingLights(Frame& f, const std::vector<Object>& scene) {
    const int n = f.option("lights");
    for (int i = 0; i < n; ++i) {
      const glm::vec4 light = samples_[static_cast<std::size_t>(i)];
      glStencilMask(0xFF);
      glClear(GL_STENCIL_BUFFER_BIT);  // this light's count starts at 0
      f.count("stencil_clears");
      countVolumes(f, light, false);
      if (i == checked_) saveStencil();
      if (i == 0) endPass(f, "volumes");
      glEnable(GL_STENCIL_TEST);
      glStencilFunc(GL_EQUAL, 0, 0xFF);  // a count of 0: outside every volume
      glStencilMask(0x80);               // counts stay below 128 (two convex casters)
      glStencilOp(GL_KEEP, GL_KEEP, f.on("update-bit") ? GL_INVERT : GL_KEEP);  // 0 -> 128: added once
      illuminate(f, scene, light);
      if (i == 0) endPass(f, "illumination");
    }
    if (n > 1) endPass(f, "other-lights");
    glStencilMask(0xFF);
  }

  // One light's closed volumes counted by z-fail into the stencil: in the whole stencil, or with
  // the wedges (inWedges) into kCountBits only, and only on pixels whose kWedgeBit is set.
  void countVolumes(Frame& f, const glm::vec4& light, bool inWedges) {
    if (f.on("shadow")) {
      volumeState(f);
      glDepthFunc(GL_LESS);  // behind the scene: fail
      if (inWedges) {
        glStencilFunc(GL_EQUAL, kWedgeBit, kWedgeBit);
        glStencilMask(kCountBits);  // INCR and DECR wrap modulo 16 there
      } else {
        glStencilFunc(GL_ALWAYS, 0, 0xFF);
        glStencilMask(f.on("wedges") ? kCountBits : 0xFFu);
      }
      glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);   // behind: the ray leaves a volume
      glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);  // behind: it enters one
      for (const PreparedCaster* c : casters(f)) {
        const ClosedVolume v = closedVolume(c->mesh, c->adjacency, light, kInfinity);
        const std::size_t sides = 3 * v.sideTriangles, lightCap = 3 * v.lightCapTriangles;
        volumeStream_.upload(v.triangles.vertices);
        volume_.set("transform", f.projection * f.view);
        volume_.set("colour", glm::vec4(1.0f, 0.85f, 0.2f, 1.0f));
        volumeStream_.draw(0, static_cast<GLsizei>(sides));  // the sides
        // The dark cap at infinity fails LESS by itself.
        volumeStream_.draw(static_cast<GLint>(sides + lightCap),
                           static_cast<GLsizei>(3 * v.darkCapTriangles));
        glDepthFunc(GL_NEVER);  // the light cap lies on the caster's surface: never in front of it
        volumeStream_.draw(static_cast<GLint>(sides), static_cast<GLsizei>(lightCap));
        glDepthFunc(GL_LESS);
        f.count("volume_triangles", v.triangles.triangleCount());
      }
      restoreState();
    }
  }

  // ---- penumbra wedges: N lights only where they can disagree ----------------------------------

  void wedgeLights(Frame& f, const std::vector<Object>& scene, const AreaLight& area) {
    const int n = f.option("lights");
    glStencilMask(0xFF);
    glClear(GL_STENCIL_BUFFER_BIT);
    f.count("stencil_clears");
    // 1. The wedges into kWedgeBit, one at a time: z-fail parity in kTempBit is 1 exactly on the
    //    surfaces inside a convex wedge; the wedge's faces then copy it into kWedgeBit and clear it.
    if (f.on("shadow")) {
      std::vector<glm::vec4> wedges;
      std::vector<std::pair<GLint, GLsizei>> ranges;
      const float scale = 1.02f * static_cast<float>(f.option("wedge-size")) / 100.0f;  // 2% to spare
      for (const PreparedCaster* c : casters(f)) penumbraWedges(*c, area, scale, wedges, ranges);
      volumeState(f);
      volumeStream_.upload(wedges);
      for (const auto& [first, count] : ranges) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glStencilFunc(GL_ALWAYS, 0, 0xFF);
        glStencilMask(kTempBit);
        glStencilOp(GL_KEEP, GL_INVERT, GL_KEEP);  // a face behind the surface: one crossing
        volumeStream_.draw(first, count);
        glDisable(GL_DEPTH_TEST);
        glStencilFunc(GL_EQUAL, kTempBit | kWedgeBit, kTempBit);  // inside: mark
        glStencilMask(kWedgeBit);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        volumeStream_.draw(first, count);
        glStencilFunc(GL_EQUAL, kTempBit, kTempBit);  // only where it is set: the rest fails early
        glStencilMask(kTempBit);
        glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);  // kTempBit back to 0 for the next wedge
        volumeStream_.draw(first, count);
      }
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_LESS);
      f.count("wedges", ranges.size());
      f.count("wedge_triangles", wedges.size() / 3);
      // A caster's own faces are shadowed by its volumes wherever they face away from the light
      // (not only behind an edge): its pixels are marked too, through the ambient pass's depths.
      glStencilFunc(GL_ALWAYS, kWedgeBit, 0xFF);
      glStencilMask(kWedgeBit);
      glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
      glDepthFunc(GL_EQUAL);
      std::vector<Object> casterObjects;
      for (const Object& o : scene)
        if (o.caster) casterObjects.push_back(o);
      drawScene(f, casterObjects, glm::vec4(0, 1, 0, 0), glm::vec3(0.0f), glm::vec3(0.0f), false);
      glDepthFunc(GL_LESS);
      glDisable(GL_STENCIL_TEST);
      restoreState();
    }
    endPass(f, "wedges");
    // 2. One light decides outside the wedges (all agree there): the checked light's count
    //    everywhere, and every light added at once where it is 0.
    countVolumes(f, samples_[static_cast<std::size_t>(checked_)], false);
    saveStencil();
    endPass(f, "volumes");
    const GLuint tested = kWedgeBit | kCountBits | kAddedBit;
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 0, tested);  // outside the wedges, lit
    glStencilMask(kAddedBit);
    glStencilOp(GL_KEEP, GL_KEEP, f.on("update-bit") ? GL_INVERT : GL_KEEP);
    illuminate(f, scene, glm::vec4(0.0f), true);
    // 3. Inside the wedges, the plain loop: each light's count, each light added where it is 0.
    for (int i = 0; i < n; ++i) {
      const glm::vec4 light = samples_[static_cast<std::size_t>(i)];
      glStencilMask(kCountBits | kAddedBit);
      glClear(GL_STENCIL_BUFFER_BIT);  // the wedges' bit stays
      f.count("stencil_clears");
      countVolumes(f, light, true);
      glEnable(GL_STENCIL_TEST);
      glStencilFunc(GL_EQUAL, kWedgeBit, tested);  // in a wedge, lit by light i
      glStencilMask(kAddedBit);
      glStencilOp(GL_KEEP, GL_KEEP, f.on("update-bit") ? GL_INVERT : GL_KEEP);
      illuminate(f, scene, light);
      if (i == 0) endPass(f, "illumination");
    }
    if (n > 1) endPass(f, "other-lights");
    glStencilMask(0xFF);
  }

  std::vector<const PreparedCaster*> casters(const Frame& f) const {
    std::vector<const PreparedCaster*> c;
    if (f.option("casters") & 1) c.push_back(&slabEdges_);
    if (f.option("casters") & 2) c.push_back(&ballEdges_);
    return c;
  }

  // Volumes touch only the stencil: no colour, no depth, both faces (unless a variant leaves a
  // state on, to show why it is off).
  void volumeState(const Frame& f) {
    const GLboolean colour = f.on("volume-colour") ? GL_TRUE : GL_FALSE;
    glColorMask(colour, colour, colour, GL_FALSE);
    glDepthMask(f.on("volume-depth") ? GL_TRUE : GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_STENCIL_TEST);
    volume_.set("transform", f.projection * f.view);
    volume_.set("colour", glm::vec4(1.0f, 0.85f, 0.2f, 1.0f));
  }
  void restoreState() {
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
  }

  void drawVolume(Frame& f, const ShadowVolume& v) {
    volumeStream_.upload(v.vertices);
    volumeStream_.draw();
    f.count("volume_triangles", v.triangleCount());
  }

  // The checked light's stencil, kept for the end of the frame (and the oracle).
  void saveStencil() {
    blit(target_->fbo(), saved_->fbo(), size_, GL_STENCIL_BUFFER_BIT);
    target_->bind();
  }

  // One light added onto the ambient pass's surfaces where the stencil test (set by the caller)
  // passes.
  // allLights: every light of the round in one draw (outside the wedges), light unused.
  void illuminate(Frame& f, const std::vector<Object>& scene, const glm::vec4& light,
                  bool allLights = false) {
    glDepthMask(GL_FALSE);  // the surfaces stay
    if (f.on("depth-equal")) {
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_EQUAL);  // exactly the ambient pass's surfaces
    } else {
      glDisable(GL_DEPTH_TEST);
    }
    if (f.on("blend")) {
      glEnable(GL_BLEND);
      glBlendFunc(GL_ONE, GL_ONE);  // light adds up; alpha counts the lights that reached
    }
    drawScene(f, scene, light, kLightColour * share(f), glm::vec3(0.0f), f.on("visibility"), allLights);
    f.count("illumination_draws");
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
  }

  // visibility: receivers only, unshaded, 1/N of white each (the fraction of the light seen).
  // allLights: every light of samples_ summed in one draw, each at `colour`; in visibility, the N
  // shares added in the lights' order, as N blended draws would add them.
  void drawScene(const Frame& f, const std::vector<Object>& scene, glm::vec4 light, glm::vec3 colour,
                 glm::vec3 ambient, bool visibility, bool allLights = false) {
    glEnable(GL_CULL_FACE);  // closed casters and the ground seen from above
    if (visibility) {
      const float s = share(f);
      glm::vec4 c(s, s, s, 1.0f);
      if (allLights) {
        float sum = 0.0f;
        for (std::size_t i = 0; i < samples_.size(); ++i) sum += s;
        c = glm::vec4(sum, sum, sum, static_cast<float>(samples_.size()));
      }
      flat_.set("colour", c);
      for (std::size_t k = scene.size(); k-- > 0;) {  // the mat before the ground, as below
        const Object& o = scene[k];
        if (o.caster) continue;  // the ground and the mat: the reference's receivers
        flat_.set("transform", f.projection * f.view * o.model);
        o.gpu->draw();
      }
      glDisable(GL_CULL_FACE);
      return;
    }
    const Program& program = allLights ? lights_ : light_;
    program.set("viewProjection", f.projection * f.view);
    program.set("lightColour", colour);
    program.set("eye", f.eye);
    program.set("shininess", 24.0f);
    if (allLights) {
      glActiveTexture(GL_TEXTURE1);
      glBindTexture(GL_TEXTURE_2D, lightsTexture_);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, static_cast<GLsizei>(samples_.size()), 1, 0, GL_RGBA,
                   GL_FLOAT, samples_.data());
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glActiveTexture(GL_TEXTURE0);
      program.set("lights", 1);
      program.set("count", static_cast<int>(samples_.size()));
    } else {
      light_.set("ambient", ambient);
      light_.set("light", light);
    }
    // Adding light, the mat goes before the ground it lies on: the surface the ambient pass left
    // on top is the one that takes the light (the other then fails the updated bit).
    const bool adding = colour != glm::vec3(0.0f);
    for (std::size_t k = 0; k < scene.size(); ++k) {
      const Object& o = scene[adding && k < 2 && scene.size() > 1 && !scene[1].caster ? 1 - k : k];
      program.set("model", o.model);
      program.set("colour", o.colour);
      o.gpu->draw();
    }
    glDisable(GL_CULL_FACE);
  }

  // A texture onto the bound framebuffer, one texel per pixel.
  void drawPicture(const Target& from, int lights, bool tint) {
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, from.colour());
    resolve_.set("transform", glm::mat4(1.0f));
    resolve_.set("picture", 0);
    resolve_.set("lights", static_cast<float>(lights));
    resolve_.set("tint", tint ? 1 : 0);
    window_.draw();
    glEnable(GL_DEPTH_TEST);
  }

  // ---- the penumbra's width, measured on the picture ------------------------------------------

  // Where the picture is the visible fraction of a rectangular light past the slab alone: walk
  // out of the slab's shadow across its +x edge (along the ground line z = the slab's centre) and
  // across its +z edge (x = the slab's centre), reading the picture at each ground point's pixel,
  // and time the ramp from 2% to 98% of the light; over 0.96 it is the whole ramp's width. Reported
  // in thousandths of a unit beside W h / (H - h) for the slab's mid-plane h
  // (geometry/soft_shadow.h's straightEdgePenumbraWidth).
  void measurePenumbra(Frame& f, const Target& picture, const AreaLight& area) {
    if (!(f.on("visibility") || f.on("reference")) || f.on("disk") || f.option("casters") != 1 ||
        f.option("size") == 0)
      return;
    std::vector<float> pixels(static_cast<std::size_t>(4 * f.size.x * f.size.y));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, picture.fbo());
    glReadPixels(0, 0, f.size.x, f.size.y, GL_RGBA, GL_FLOAT, pixels.data());
    const glm::mat4 viewProjection = f.projection * f.view;
    auto rampWidth = [&](glm::vec3 from, glm::vec3 step) {
      float at02 = -1.0f, at98 = -1.0f;
      for (int k = 0; k < 400; ++k) {
        const glm::vec3 p = from + static_cast<float>(k) * step;
        const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
        const glm::vec2 window = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(f.size);
        const int x = static_cast<int>(window.x), y = static_cast<int>(window.y);
        if (x < 0 || y < 0 || x >= f.size.x || y >= f.size.y) continue;
        const float v = pixels[static_cast<std::size_t>(4 * (y * f.size.x + x))];
        const float s = static_cast<float>(k) * glm::length(step);
        if (at02 < 0.0f && v >= 0.02f) at02 = s;
        if (at98 < 0.0f && v >= 0.98f) at98 = s;
      }
      return at02 < 0.0f || at98 < 0.0f ? 0.0 : static_cast<double>(at98 - at02) / 0.96;
    };
    const double H = kLightHeight, h = kSlabHeight;
    // From under the slab's middle outwards, 2 units in steps of 0.005.
    const double wx = rampWidth({kSlabCentre.x, 0.0f, kSlabCentre.z}, {0.005f, 0.0f, 0.0f});
    const double wz = rampWidth({kSlabCentre.x, 0.0f, kSlabCentre.z}, {0.0f, 0.0f, 0.005f});
    f.count("penumbra_width_x_milli", static_cast<std::uint64_t>(std::lround(1000.0 * wx)));
    f.count("penumbra_width_z_milli", static_cast<std::uint64_t>(std::lround(1000.0 * wz)));
    f.count("penumbra_width_x_predicted_milli",
            static_cast<std::uint64_t>(std::lround(1000.0 * straightEdgePenumbraWidth(area.size.x, H, h))));
    f.count("penumbra_width_z_predicted_milli",
            static_cast<std::uint64_t>(std::lround(1000.0 * straightEdgePenumbraWidth(area.size.y, H, h))));
  }

  // ---- the exact answer --------------------------------------------------------------------------

  // Per pixel centre: the eye ray onto the ground (if the slab does not hide it) and the ground
  // point's visible fraction of the area light (geometry/soft_shadow.h), written into the target.
  void drawReference(Frame& f, const AreaLight& area, const glm::mat4& viewProjection) {
    const glm::mat4 inverse = glm::inverse(viewProjection);
    const glm::vec3 lo = kSlabCentre - 0.5f * glm::vec3(kSlabSide, kSlabThickness, kSlabSide);
    const glm::vec3 hi = kSlabCentre + 0.5f * glm::vec3(kSlabSide, kSlabThickness, kSlabSide);
    std::vector<glm::vec3> corners;
    for (int i = 0; i < 8; ++i)
      corners.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    const float n = static_cast<float>(f.option("lights"));
    // What the ambient pass left (the background, the casters) stays; ground pixels are replaced.
    std::vector<float> pixels(static_cast<std::size_t>(4 * f.size.x * f.size.y), 0.0f);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, target_->fbo());
    glReadPixels(0, 0, f.size.x, f.size.y, GL_RGBA, GL_FLOAT, pixels.data());
    for (int y = 0; y < f.size.y; ++y)
      for (int x = 0; x < f.size.x; ++x) {
        const glm::vec2 ndc(2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(f.size.x) - 1.0f,
                            2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(f.size.y) - 1.0f);
        const glm::vec4 a = inverse * glm::vec4(ndc, -1.0f, 1.0f), b = inverse * glm::vec4(ndc, 0.0f, 1.0f);
        const glm::dvec3 origin = glm::dvec3(glm::vec3(a) / a.w);
        const glm::dvec3 direction = glm::dvec3(glm::vec3(b) / b.w) - origin;
        if (direction.y >= 0.0) continue;
        const double t = -origin.y / direction.y;
        const glm::dvec3 p = origin + t * direction;
        if (std::abs(p.x) > kGroundHalf || std::abs(p.z) > kGroundHalf) continue;
        if (rayHitsBox(origin, direction, t, glm::dvec3(lo), glm::dvec3(hi))) continue;
        const float v = static_cast<float>(visibleFraction(area, corners, glm::vec3(p)));
        float* px = &pixels[static_cast<std::size_t>(4 * (y * f.size.x + x))];
        px[0] = px[1] = px[2] = v;
        px[3] = v * n;
      }
    glBindTexture(GL_TEXTURE_2D, target_->colour());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, f.size.x, f.size.y, GL_RGBA, GL_FLOAT, pixels.data());
    endPass(f, "illumination");
  }

  // The same picture for any casters: per pixel, the eye ray's first hit and, where that is a
  // receiver, the fraction of 2^converged stratified shadow rays to the light that nothing blocks
  // (geometry/soft_shadow_reference.h, through occlusionBackend()).
  void drawConverged(Frame& f, const std::vector<Object>& scene, const AreaLight& area,
                     const glm::mat4& viewProjection) {
    OcclusionScene rays;
    std::vector<bool> receives;
    for (const Object& o : scene) {
      rays.add(*o.mesh, o.model);
      receives.push_back(!o.caster);
    }
    const int k = 1 << f.option("converged");
    f.count("reference_rays_per_pixel", static_cast<std::uint64_t>(k));
    const std::vector<float> fraction = convergedVisibility(
        rays, [&](int object) { return receives[static_cast<std::size_t>(object)]; }, area,
        glm::inverse(viewProjection), f.size, k, 0,
        [&](std::size_t done, std::size_t total) { f.progress("pixels ray cast", done, total); });
    const float n = static_cast<float>(f.option("lights"));
    std::vector<float> pixels(static_cast<std::size_t>(4 * f.size.x * f.size.y), 0.0f);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, target_->fbo());
    glReadPixels(0, 0, f.size.x, f.size.y, GL_RGBA, GL_FLOAT, pixels.data());
    for (std::size_t i = 0; i < fraction.size(); ++i) {
      if (fraction[i] < 0.0f) continue;  // the background and the casters stay as the ambient pass left them
      float* px = &pixels[4 * i];
      px[0] = px[1] = px[2] = fraction[i];
      px[3] = fraction[i] * n;
    }
    glBindTexture(GL_TEXTURE_2D, target_->colour());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, f.size.x, f.size.y, GL_RGBA, GL_FLOAT, pixels.data());
    endPass(f, "illumination");
  }

  // Whether origin + s direction meets the box for some s in [0, t).
  static bool rayHitsBox(glm::dvec3 origin, glm::dvec3 direction, double t, glm::dvec3 lo, glm::dvec3 hi) {
    double t0 = 0.0, t1 = t;
    for (int k = 0; k < 3; ++k) {
      if (direction[k] == 0.0) {
        if (origin[k] < lo[k] || origin[k] > hi[k]) return false;
        continue;
      }
      double ta = (lo[k] - origin[k]) / direction[k], tb = (hi[k] - origin[k]) / direction[k];
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
      if (t0 >= t1) return false;
    }
    return true;
  }

  // Stencil bits with the wedges: the count in the low four (two convex casters count to 2,
  // wrapping modulo 16 on the way), a wedge's z-fail parity, the wedges' union, the added bit.
  static constexpr GLuint kCountBits = 0x0F, kTempBit = 0x20, kWedgeBit = 0x40, kAddedBit = 0x80;

  // ---- the targets ------------------------------------------------------------------------------

  // A colour texture (RGBA16F, RGBA8 or RGBA32F) with, optionally, a packed depth/stencil buffer of
  // the framework's format, so depth and stencil blit to it unchanged.
  class Target {
   public:
    Target(glm::ivec2 size, GLenum colourFormat, bool depthStencil) : size_(size), format_(colourFormat) {
      glGenFramebuffers(1, &fbo_);
      glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
      glGenTextures(1, &colour_);
      glBindTexture(GL_TEXTURE_2D, colour_);
      glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(colourFormat), size.x, size.y, 0, GL_RGBA, GL_FLOAT,
                   nullptr);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_, 0);
      if (depthStencil) {
        glGenRenderbuffers(1, &depthStencil_);
        glBindRenderbuffer(GL_RENDERBUFFER, depthStencil_);
        glRenderbufferStorage(GL_RENDERBUFFER, depthStencilFormat(DepthFormat::Fixed24), size.x, size.y);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                  depthStencil_);
      }
      if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("lesson 10's accumulation framebuffer is incomplete");
    }
    ~Target() {
      glDeleteFramebuffers(1, &fbo_);
      glDeleteTextures(1, &colour_);
      if (depthStencil_) glDeleteRenderbuffers(1, &depthStencil_);
    }
    Target(const Target&) = delete;
    Target& operator=(const Target&) = delete;

    bool fits(glm::ivec2 size, GLenum format) const { return size == size_ && format == format_; }
    void bind() const {
      glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
      glViewport(0, 0, size_.x, size_.y);
    }
    GLuint fbo() const { return fbo_; }
    GLuint colour() const { return colour_; }

   private:
    glm::ivec2 size_;
    GLenum format_;
    GLuint fbo_ = 0, colour_ = 0, depthStencil_ = 0;
  };

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

  // ---- test hooks ---------------------------------------------------------------------------------

 public:
  // The checked light's stencil against a ray cast from that light: counting keeps its count
  // (0 lit), Kilgard its bit.
  std::optional<ShadowCheck> shadowCheck(const Frame& f) const override {
    if (!f.on("shadow") || f.on("reference") || samples_.empty()) return std::nullopt;
    const bool kilgard = f.option("method") == 1;
    const std::uint8_t bit = static_cast<std::uint8_t>(1u << (checked_ % 8));
    // With the wedges the saved stencil also holds the wedges' bit; the count is in the low bits.
    const auto countMask = static_cast<std::uint8_t>(f.on("wedges") ? kCountBits : 0xFFu);
    ShadowCheck check{
        {},
        samples_[static_cast<std::size_t>(checked_)],
        [kilgard, bit, countMask](std::uint8_t s) { return kilgard ? (s & bit) == 0 : (s & countMask) == 0; },
        true};
    for (const Object& o : sceneOf(f)) check.objects.push_back({o.mesh, o.model, o.caster, true});
    return check;
  }
};

// ---- the scene's pieces ----------------------------------------------------------------------------

AreaLight areaLight(const Frame& f) {
  const float width = 0.1f * static_cast<float>(f.option("size"));
  return {{0.0f, kLightHeight, 0.0f},
          {width, width * 2.0f / 3.0f},
          f.on("disk") ? LightShape::Disk : LightShape::Rectangle};
}

glm::mat4 slabModel() {
  return glm::scale(glm::translate(glm::mat4(1.0f), kSlabCentre), {kSlabSide, kSlabThickness, kSlabSide});
}

// The ground's triangles whose centre lies in the mat's square, the same vertices: the mat's
// depths are the ground's to the last bit, so depth EQUAL passes both.
Mesh matFrom(const Mesh& ground) {
  Mesh mat;
  for (std::size_t t = 0; t + 2 < ground.indices.size(); t += 3) {
    glm::vec3 c(0.0f);
    for (int k = 0; k < 3; ++k) c += ground.positions[ground.indices[t + static_cast<std::size_t>(k)]];
    c /= 3.0f;
    if (c.x < 0.5f || c.x > 2.0f || c.z < -1.0f || c.z > 1.0f) continue;  // whole cells of 0.5
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = ground.indices[t + static_cast<std::size_t>(k)];
      mat.indices.push_back(static_cast<std::uint32_t>(mat.positions.size()));
      mat.positions.push_back(ground.positions[i]);
      mat.normals.push_back(ground.normals[i]);
    }
  }
  return mat;
}

// ---- penumbra wedges (Assarsson and Akenine-Moller, "A Geometry-Based Soft Shadow Volume
// Algorithm Using Graphics Hardware", SIGGRAPH 2003) --------------------------------------------

constexpr float kWedgeFloor = -0.5f;  // wedges end below every receiver (the ground is y = 0)

// The convex hull of a few points (a dozen: every plane through three of them with all the others
// on one side holds a face), as triangles counter-clockwise seen from outside, w = 1. Points
// within 1e-6 of the hull's size from a face's plane belong to that face. Empty when the points
// span no volume.
std::vector<glm::vec4> convexHull(const std::vector<glm::dvec3>& p) {
  std::vector<glm::vec4> triangles;
  double size = 0.0;
  for (const glm::dvec3& q : p) size = std::max(size, glm::length(q - p[0]));
  const double eps = 1e-6 * size;
  std::vector<std::vector<std::size_t>> faces;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      for (std::size_t k = j + 1; k < p.size(); ++k) {
        glm::dvec3 normal = glm::cross(p[j] - p[i], p[k] - p[i]);
        const double length = glm::length(normal);
        if (length <= 1e-12 * size * size) continue;
        normal /= length;
        bool below = true, above = true;
        std::vector<std::size_t> on;
        for (std::size_t m = 0; m < p.size(); ++m) {
          const double d = glm::dot(normal, p[m] - p[i]);
          if (d > eps) below = false;
          if (d < -eps) above = false;
          if (std::abs(d) <= eps) on.push_back(m);
        }
        if (below == above) continue;  // points on both sides, or all on the plane
        if (!below) normal = -normal;  // outward: the others lie behind the face
        if (std::find(faces.begin(), faces.end(), on) != faces.end()) continue;
        faces.push_back(on);
        // The face's points in order: a 2D hull (monotone chain) in the plane's (u, v), u x v the
        // outward normal, so counter-clockwise there is counter-clockwise from outside.
        const glm::dvec3 u = glm::normalize(p[on[1]] - p[on[0]]), v = glm::cross(normal, u);
        std::vector<std::pair<glm::dvec2, std::size_t>> flat;
        for (std::size_t m : on) flat.push_back({{glm::dot(p[m], u), glm::dot(p[m], v)}, m});
        std::sort(flat.begin(), flat.end(), [](const auto& a, const auto& b) {
          return a.first.x < b.first.x || (a.first.x == b.first.x && a.first.y < b.first.y);
        });
        auto turn = [](glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) {
          return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
        };
        std::vector<std::size_t> ring;  // positions in flat
        for (int pass = 0; pass < 2; ++pass) {
          const std::size_t start = ring.size();
          for (std::size_t t = 0; t < flat.size(); ++t) {
            const std::size_t at = pass == 0 ? t : flat.size() - 1 - t;
            while (ring.size() >= start + 2 && turn(flat[ring[ring.size() - 2]].first,
                                                    flat[ring.back()].first, flat[at].first) <= eps * size)
              ring.pop_back();
            ring.push_back(at);
          }
          ring.pop_back();  // the chain's last point starts the other chain
        }
        for (std::size_t t = 1; t + 1 < ring.size(); ++t)
          for (std::size_t corner : {ring[0], ring[t], ring[t + 1]})
            triangles.push_back(glm::vec4(glm::vec3(p[flat[corner].second]), 1.0f));
      }
  return triangles;
}

// Every wedge of a caster (welded, world space): for each edge that may be a silhouette edge from
// some point of the light's bounding rectangle, grown by `scale` (its two faces neither both
// front-facing nor both back-facing from all four corners; a border edge always), the convex hull
// of the edge and its endpoints extruded away from each corner down to y = kWedgeFloor. Every
// shadow-volume side of the edge from a light point inside the rectangle lies in that hull (its
// points are convex combinations of the corners' sides), so a receiver whose lights disagree lies
// in some wedge. Appends the triangles (w = 1) and each wedge's (first vertex, vertex count).
// Throws std::logic_error for an edge at or above the light (the lesson's scene has none).
void penumbraWedges(const PreparedCaster& caster, const AreaLight& area, float scale,
                    std::vector<glm::vec4>& out, std::vector<std::pair<GLint, GLsizei>>& ranges) {
  const glm::dvec2 half = 0.5 * static_cast<double>(scale) *
                          glm::dvec2(area.shape == LightShape::Disk ? glm::vec2(area.size.x) : area.size);
  const glm::dvec3 centre(area.centre);
  const std::array<glm::dvec3, 4> corners{
      centre + glm::dvec3(-half.x, 0.0, -half.y), centre + glm::dvec3(half.x, 0.0, -half.y),
      centre + glm::dvec3(half.x, 0.0, half.y), centre + glm::dvec3(-half.x, 0.0, half.y)};
  const std::vector<glm::vec3>& position = caster.mesh.positions;
  const std::vector<std::uint32_t>& index = caster.mesh.indices;
  auto faces = [&](std::int32_t face, const glm::dvec3& light) {
    const glm::dvec3 a(position[index[3 * static_cast<std::size_t>(face)]]);
    const glm::dvec3 b(position[index[3 * static_cast<std::size_t>(face) + 1]]);
    const glm::dvec3 c(position[index[3 * static_cast<std::size_t>(face) + 2]]);
    return glm::dot(glm::cross(b - a, c - a), light - a) > 0.0;
  };
  for (const Edge& e : caster.adjacency.edges) {
    if (e.face0 >= 0 && e.face1 >= 0) {
      bool allFront = true, allBack = true;
      for (const glm::dvec3& c : corners) {
        const bool f0 = faces(e.face0, c), f1 = faces(e.face1, c);
        allFront = allFront && f0 && f1;
        allBack = allBack && !f0 && !f1;
      }
      if (allFront || allBack) continue;  // never a silhouette edge
    }
    std::vector<glm::dvec3> points{glm::dvec3(position[e.v0]), glm::dvec3(position[e.v1])};
    for (const glm::dvec3& c : corners)
      for (std::size_t k = 0; k < 2; ++k) {
        const glm::dvec3 q = points[k];
        if (c.y - q.y < 1e-3) throw std::logic_error("a penumbra wedge's edge at or above the light");
        points.push_back(q + (q.y - kWedgeFloor) / (c.y - q.y) * (q - c));
      }
    const std::vector<glm::vec4> hull = convexHull(points);
    if (hull.empty()) continue;
    ranges.push_back({static_cast<GLint>(out.size()), static_cast<GLsizei>(hull.size())});
    out.insert(out.end(), hull.begin(), hull.end());
  }
}

// Copies what `mask` names from one framebuffer to another of the same size.
void blit(GLuint from, GLuint to, glm::ivec2 size, GLbitfield mask) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, from);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to);
  glBlitFramebuffer(0, 0, size.x, size.y, 0, 0, size.x, size.y, mask, GL_NEAREST);
}

// ---- the lesson: options, variants, camera -------------------------------------------------------

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "10-soft-shadows";
  info.title = "Soft shadows from light clusters";
  info.summary =
      "An area light sampled by N point lights, each with a hard shadow volume, each added at 1/N where\n"
      "its shadow is not: Kilgard's eight stencil bits, where they fail, and a count per light in float.";
  info.options = {
      {"method", 'M',
       "0 counting: per light a z-fail count in the whole stencil; 1 Kilgard: per light one stencil bit,\n"
       "      inverted by its volumes (z-pass parity), eight lights to a stencil clear",
       0, 1},
      {"lights", 'N', "the point lights sampling the area light", 16, kMaxLights, 1},
      {"pattern", 'T', "where the lights sit: 0 a grid, 1 jittered (one random point per cell), 2 Halton", 1,
       2},
      {"disk", 'D', "a disk light instead of the rectangle", 0},
      {"size", 'I', "the light's width in tenths of a unit (depth: two thirds of it); 0 a point", 15, 30},
      {"float", 'F',
       "the accumulation target: 1 RGBA32F, 2 RGBA16F (an 11-bit mantissa: N additions near 1 each round),\n"
       "      0 RGBA8 (each light's term rounded to 1/255)",
       1, 2},
      {"scale", 'W', "each light adds 1/N of the area light (off: the whole light each)", 1},
      {"update-bit", 'U', "adding a light sets the stencil bit it tested: one addition per pixel per light",
       1},
      {"depth-equal", 'E', "light only the ambient pass's surfaces (depth EQUAL; off: no depth test)", 1},
      {"blend", 'B', "add the lights (off: each replaces what is there)", 1},
      {"bit-mask", 'K', "Kilgard: a light's volumes write only its own bit (off: all eight bits)", 1},
      {"volume-colour", 'C', "the volumes also write colour (a state left on)", 0},
      {"volume-depth", 'Z', "the volumes also write depth (a state left on)", 0},
      {"reclear", 'J', "Kilgard past eight lights: clear the stencil before each group of eight", 1},
      {"casters", 'A', "1 the slab, 2 a ball, 3 both (their volumes overlap)", 1, 3, 1},
      {"mat", 'G', "a mat on the ground made of the ground's own triangles (equal depths)", 1},
      {"visibility", 'Y',
       "each light adds 1/N of white, unshaded, to the ground: the picture is the visible fraction", 0},
      {"reference", 'Q', "the exact visible fraction (analytic; the slab only) instead of the lights", 0},
      {"converged", '4',
       "the reference ray cast instead, any casters: 2^converged stratified shadow rays per pixel\n"
       "      (geometry/soft_shadow_reference.h; 0: the analytic one)",
       0, 14},
      {"progressive", 'O', "each frame adds N new samples to a running average", 0},
      {"penumbra", 'X', "tint the penumbra: pixels some lights reach and some do not (float only)", 0},
      {"light", 'L', "the light whose hard shadow the final stencil holds (the one --oracle checks)", 0,
       kMaxLights - 1},
      {"shadow", 'H', "shadows at all (off: every light reaches everything)", 1},
      {"wedges", '1',
       "penumbra wedges (counting only): the N-light loop only in the wedges' pixels, one light's hard\n"
       "      shadow deciding everywhere else",
       0},
      {"show-wedges", '2', "tint the pixels the wedges mark (wedges only)", 0},
      {"wedge-size", '3',
       "the light the wedges are built from, in percent of the real one (test hook: under 100 the wedges\n"
       "      miss part of the penumbra)",
       100, 100},
  };
  info.variants = {
      {"counting",
       "sixteen jittered lights, each counted by z-fail in the whole stencil, float accumulation",
       {}},
      {"kilgard-8",
       "Kilgard's recipe: eight lights on a grid, a stencil bit each, 1/8 each",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}}},
      {"kilgard-no-update-bit",
       "the tested bit not set when the light is added: the mat adds each light twice",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}, {"update-bit", 0}}},
      {"kilgard-no-depth-equal",
       "no depth test when the lights are added: hidden ground lights the slab",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}, {"depth-equal", 0}}},
      {"kilgard-no-blend",
       "each light replaces the last: only the eighth remains",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}, {"blend", 0}}},
      {"kilgard-no-scale",
       "each light at full intensity: eight times too bright",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}, {"scale", 0}}},
      {"kilgard-no-bit-mask",
       "each light's volumes invert all eight bits: the shadows mix",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}, {"bit-mask", 0}}},
      {"kilgard-volume-colour",
       "colour writes left on while the volumes are drawn",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}, {"volume-colour", 1}}},
      {"kilgard-volume-depth",
       "depth writes left on while the volumes are drawn: EQUAL fails behind them",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}, {"volume-depth", 1}}},
      {"kilgard-overlap",
       "two casters whose volumes overlap: parity lights the overlap",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}, {"casters", 3}, {"light", 7}}},
      {"counting-overlap",
       "the same two casters counted: the overlap stays dark",
       {{"casters", 3}, {"light", 7}}},
      {"kilgard-16",
       "sixteen lights in two groups of eight, the stencil cleared between them",
       {{"method", 1}, {"lights", 16}, {"pattern", 0}}},
      {"kilgard-16-no-reclear",
       "sixteen lights without the clear: lights 8-15 find their bits set, add nothing",
       {{"method", 1}, {"lights", 16}, {"pattern", 0}, {"reclear", 0}, {"light", 8}}},
      {"kilgard-8-8bit",
       "Kilgard's eight lights added in an RGBA8 buffer: each 1/8 term rounded",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}, {"float", 0}}},
      {"banding",
       "four lights on a grid: five levels, bands across the penumbra",
       {{"lights", 4}, {"pattern", 0}}},
      {"many-8bit",
       "256 lights in RGBA8: the terms below one level vanish",
       {{"lights", 256}, {"float", 0}, {"pattern", 2}}},
      {"many", "256 Halton lights in RGBA32F", {{"lights", 256}, {"pattern", 2}}},
      {"many-16f",
       "256 Halton lights in RGBA16F: rounding near 1 adds up over the lights",
       {{"lights", 256}, {"pattern", 2}, {"float", 2}}},
      {"disk", "a disk light, 64 Halton lights", {{"lights", 64}, {"pattern", 2}, {"disk", 1}}},
      {"visibility",
       "64 Halton lights, the visible fraction unshaded",
       {{"lights", 64}, {"pattern", 2}, {"visibility", 1}}},
      {"reference", "the exact visible fraction, analytic", {{"reference", 1}, {"visibility", 1}}},
      {"converged",
       "the visible fraction past the slab and the ball, ray cast with 1024 shadow rays per pixel",
       {{"reference", 1}, {"visibility", 1}, {"converged", 10}, {"casters", 3}}},
      {"penumbra", "the penumbra tinted", {{"penumbra", 1}}},
      {"wedges",
       "sixteen jittered lights, the N-light loop only inside the penumbra wedges",
       {{"wedges", 1}}},
      {"wedges-marked",
       "the pixels the penumbra wedges mark, tinted: the only ones where N lights run",
       {{"wedges", 1}, {"show-wedges", 1}, {"casters", 3}}},
  };
  info.shadows = true;
  // Snapshots after the first light's (or first eight's) volumes and illumination, then after all
  // the others: a pass per light would copy the frame once per light.
  info.passes = {"ambient", "wedges", "volumes", "illumination", "other-lights", "resolve"};
  info.camera.target = {0.2f, 0.3f, 0.3f};
  info.camera.distance = 6.6f;
  info.camera.azimuthDeg = 20.0f;
  info.camera.elevationDeg = 52.0f;
  info.camera.farPlane = kInfinity;  // z-fail's dark caps at infinity stay in the frustum
  info.refuseOptions = [](const OptionsChosen& o) -> std::string {
    if (o.set("light") && o.value("light") >= o.value("lights"))
      return "--set light=" + std::to_string(o.value("light")) + ": there are " +
             std::to_string(o.value("lights")) + " lights (0 to " + std::to_string(o.value("lights") - 1) + ")";
    return {};
  };
  return info;
}

}  // namespace

int main(int argc, char** argv) {
  return runLesson(
      lessonInfo(), [] { return std::make_unique<SoftShadows>(); }, argc, argv);
}
