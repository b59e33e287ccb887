// Lesson 04: planar projected shadows without double blending (Kilgard, "Improving Shadows
// and Reflections via the Stencil Buffer", section 4 and appendix B).
//
// A shadow on a flat ground is the caster squashed onto the ground's plane along the
// lines from the light: draw the caster once more through the planar shadow matrix, in a
// translucent dark colour. Done naively that has three faults:
//   z-fighting       the flattened caster lies exactly in the ground's depth;
//   double blending  wherever the flattened caster overlaps itself, the pixel is darkened
//                    two or more times (dark blotches);
//   off the edge     the shadow hangs in mid air past the edge of a finite ground.
// The stencil fixes all three: tag the ground's visible pixels, then draw the shadow with
// the depth test off, only where the tag is, and clear the tag as each pixel is darkened.

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/bounds.h"
#include "geometry/planar.h"
#include "geometry/shapes.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/light_marker.h"
#include "gl/shader.h"

using namespace stencil;

namespace {

constexpr float kShadowAlpha = 0.5f;  // each darkening keeps half the light
constexpr GLint kGroundTag = 1;
constexpr glm::vec4 kMarkerColour{1.0f, 0.95f, 0.4f, 1.0f};

class ProjectedShadows final : public Lesson {
 public:
  ProjectedShadows()
      : lit_("common/lit.vert", "common/lit.frag"),
        flat_("common/flat.vert", "common/flat.frag"),
        shadow_("common/projected_shadow.vert", "common/flat.frag"),
        groundMesh_(makePlane(2.0f, 1)),
        holedGroundMesh_(makeSquareRing(2.0f, 0.6f)),
        torusMesh_(makeTorus(0.7f, 0.25f, 48, 24)),
        ground_(groundMesh_),
        holedGround_(holedGroundMesh_),
        torus_(torusMesh_),
        marker_(0.08f, 16, 8) {}

  void render(Frame& f) override {
    const glm::vec4 light = lightAt(f);
    const glm::vec4 groundPlane = planeFrom({0, 0, 0}, {0, 1, 0});
    const glm::mat4 caster = casterModel(f);

    // ---- the scene, with the visible ground tagged --------------------------------------
    glClearColor(0.55f, 0.65f, 0.8f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);  // closed casters: back faces are never seen
    drawLit(f, torus_, caster, {0.9f, 0.45f, 0.2f}, light);
    if (light.w != 0.0f) marker_.draw(f.projection * f.view, glm::vec3(light), kMarkerColour);
    if (f.on("stencil")) {
      glEnable(GL_STENCIL_TEST);
      glStencilFunc(GL_ALWAYS, kGroundTag, 0xFF);  // drawn after the caster, so only where
      glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);   // the ground is visible gets the tag
    }
    glDisable(GL_CULL_FACE);  // the ground is one-sided but may be seen from below
    drawLit(f, f.option("case") == kHole ? holedGround_ : ground_, glm::mat4(1), {0.75f, 0.75f, 0.7f}, light);
    f.pass("scene");

    // ---- the shadow: the caster flattened onto the ground ----------------------------------
    if (!f.on("shadow")) {
      f.pass("shadow");
      return;
    }
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_CULL_FACE);  // the faces towards the light: one layer per layer of caster
    if (f.on("stencil")) {
      glDisable(GL_DEPTH_TEST);                   // the tag says where the ground is visible
      glStencilFunc(GL_EQUAL, kGroundTag, 0xFF);  // only on tagged ground...
      glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);     // ...and only once: darkening clears the tag
    } else {
      glDepthMask(GL_FALSE);  // a shadow is not a surface: every layer of it blends
      if (f.on("offset")) {
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(-1.0f, -1.0f);  // pull the shadow towards the eye, out of the ground
      }
    }
    const glm::mat4 shadowMatrix = planarShadowMatrix(groundPlane, light);
    if (f.on("clip")) {
      glEnable(GL_CLIP_DISTANCE0);  // the shader keeps the caster's part on the light's side
      glEnable(GL_CLIP_DISTANCE1);  // of the ground and nearer to it than the light
      shadow_.set("model", caster);
      shadow_.set("shadowMatrix", shadowMatrix);
      shadow_.set("viewProjection", f.projection * f.view);
      shadow_.set("receiver", groundPlane);
      shadow_.set("light", light);
      shadow_.set("colour", glm::vec4(0.0f, 0.0f, 0.0f, kShadowAlpha));
    } else {
      // A shader that writes no clip distances: some drivers (Mesa 22's llvmpipe) clip with
      // written distances even while GL_CLIP_DISTANCEi is disabled.
      flat_.set("transform", f.projection * f.view * shadowMatrix * caster);
      flat_.set("colour", glm::vec4(0.0f, 0.0f, 0.0f, kShadowAlpha));
    }
    torus_.draw();
    glDisable(GL_CLIP_DISTANCE0);
    glDisable(GL_CLIP_DISTANCE1);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_TRUE);
    f.pass("shadow");
  }

 private:
  static constexpr int kBuried = 1, kLightBelow = 2, kLightAtTop = 3, kGrazing = 4, kHole = 5;

  // A point light circling above (w = 1), or a direction (w = 0); the hard cases move it.
  glm::vec4 lightAt(const Frame& f) const {
    const float a = 0.4f * static_cast<float>(f.time);
    switch (f.option("case")) {
      case kBuried:
        // Low and on the camera's side: a false shadow of the buried part would lie in view.
        return {3.0f * std::cos(a + 0.65f), 1.6f, 3.0f * std::sin(a + 0.65f), 1.0f};
      case kLightBelow: return {1.2f * std::cos(a), -1.5f, 1.2f * std::sin(a), 1.0f};
      case kLightAtTop: {
        const float top = boundsOf(transformed(torusMesh_, casterModel(f)).positions).max.y;
        return {1.8f * std::cos(a), top, 1.8f * std::sin(a), 1.0f};
      }
      case kGrazing: {
        const float e = glm::radians(10.0f);
        return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a), 0.0f};
      }
      default: break;
    }
    if (f.on("directional"))
      return {glm::normalize(glm::vec3(0.6f * std::cos(a), 1.0f, 0.6f * std::sin(a))), 0.0f};
    if (f.on("low-light"))
      return {3.2f * std::cos(a), 3.0f, 3.2f * std::sin(a), 1.0f};  // above the torus top
    return {1.2f * std::cos(a), 4.0f, 1.2f * std::sin(a), 1.0f};
  }

  // The torus tumbles above the ground, so from the light it often overlaps itself.
  static glm::mat4 casterModel(const Frame& f) {
    const float t = static_cast<float>(f.time);
    // Buried: its lower part under the ground. Grazing: low, so the long shadow starts on the ground.
    const float height = f.option("case") == kBuried ? 0.35f : f.option("case") == kGrazing ? 0.9f : 1.2f;
    glm::mat4 m = glm::translate(glm::mat4(1), {0.0f, height, 0.0f});
    m = glm::rotate(m, 0.5f * t, {0, 1, 0});
    return glm::rotate(m, 1.2f + 0.3f * t, {1, 0, 0.3f});
  }

  void drawLit(const Frame& f, const GpuMesh& mesh, const glm::mat4& model, glm::vec3 colour,
               glm::vec4 light) {
    // xyz is the direction towards the light from the origin for both kinds of light:
    // one direction for the whole scene is enough shading to read the shapes.
    lit_.set("model", model);
    lit_.set("viewProjection", f.projection * f.view);
    lit_.set("colour", colour);
    lit_.set("toLight", glm::normalize(glm::vec3(light)));
    lit_.set("ambient", 0.35f);
    mesh.draw();
  }

  Program lit_, flat_, shadow_;
  Mesh groundMesh_, holedGroundMesh_, torusMesh_;  // kept for the oracle's ray cast
  GpuMesh ground_, holedGround_, torus_;
  LightMarker marker_;

  // ---- test hooks ---------------------------------------------------------------------------------

 public:
  // With the stencil, the visible ground keeps its tag exactly where the light reaches it.
  std::optional<ShadowCheck> shadowCheck(const Frame& f) const override {
    if (!f.on("stencil") || !f.on("shadow")) return std::nullopt;
    const glm::vec4 light = lightAt(f);
    ShadowCheck check{
        {{&torusMesh_, casterModel(f), true, false},
         {f.option("case") == kHole ? &holedGroundMesh_ : &groundMesh_, glm::mat4(1), false, true}},
        light,
        [](std::uint8_t s) { return s == kGroundTag; }};
    if (light.w != 0.0f)
      check.objects.push_back(
          {&marker_.mesh(), glm::translate(glm::mat4(1), glm::vec3(light)), false, false});
    return check;
  }
};

// ---- the lesson: options, variants, camera -------------------------------------------------------

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "04-projected-shadows";
  info.title = "Planar projected shadows";
  info.summary =
      "The caster flattened onto the ground by the shadow matrix; z-fighting, double blending and\n"
      "shadows off the ground's edge, and the stencil recipe that removes all three.";
  info.options = {
      {"stencil", 'T', "tag the ground and draw the shadow only on the tag, once per pixel", 1},
      {"offset", 'O', "polygon offset for the unstenciled shadow (fights z-fighting only)", 0},
      {"low-light", 'L', "a low light to the side: the shadow runs past the ground's edge", 0},
      {"directional", 'D', "a directional light (w = 0) instead of a point light", 0},
      {"shadow", 'H', "draw the shadow pass at all (off: the reference the tests compare with)", 1},
      {"clip", 'C', "keep only the caster's part between the ground and the light", 1},
      {"case", 'K',
       "a hard case: 1 caster partly buried, 2 light below the ground, 3 light level with the caster's\n"
       "      top, 4 grazing directional light, 5 ground with a hole",
       0, 5},
  };
  info.variants = {
      {"stencil", "Kilgard's recipe: one darkening per pixel, only on the ground", {}},
      {"z-fighting",
       "no stencil, no offset: the shadow fights the ground for depth",
       {{"stencil", 0}, {"offset", 0}}},
      {"double-blending",
       "no stencil, polygon offset: overlaps of the flattened torus darken twice",
       {{"stencil", 0}, {"offset", 1}}},
      {"off-the-edge",
       "no stencil, a low light: the shadow hangs in the air past the edge",
       {{"stencil", 0}, {"offset", 1}, {"low-light", 1}}},
      {"off-the-edge-stencil",
       "the same low light with the stencil: the shadow ends at the edge",
       {{"low-light", 1}}},
      {"directional", "a directional light: parallel projection, same recipe", {{"directional", 1}}},
      {"buried", "the torus partly below the ground: the buried part casts nothing", {{"case", 1}}},
      {"buried-unclipped",
       "the same without clipping: the buried part projects a false shadow",
       {{"case", 1}, {"clip", 0}}},
      {"light-below", "the light below the ground: no shadow on its top side", {{"case", 2}}},
      {"light-at-top", "a light level with the torus top: the shadow runs to infinity", {{"case", 3}}},
      {"grazing", "a directional light 10 degrees above the horizon: a very long shadow", {{"case", 4}}},
      {"hole", "a ground with a hole: no shadow in the hole", {{"case", 5}}},
  };
  info.shadows = true;
  info.passes = {"scene", "shadow"};
  info.camera.distance = 7.5f;
  info.camera.elevationDeg = 35.0f;
  info.camera.target = {0.0f, 0.4f, 0.0f};
  return info;
}

}  // namespace

int main(int argc, char** argv) {
  return runLesson(
      lessonInfo(), [] { return std::make_unique<ProjectedShadows>(); }, argc, argv);
}
