// Lesson 07: shadow volumes with one inverted stencil bit (Kilgard, "Improving Shadows and
// Reflections via the Stencil Buffer", section 6.1).
//
// A caster's shadow volume is the region the light cannot see past it: bounded by the caster's
// lit faces and by quads that extrude its silhouette edges away from the light. A visible
// point is in shadow exactly when the ray from the eye to it crosses that boundary an odd
// number of times (if the eye itself is outside every volume). So: draw the lit scene, then
// draw the volume's boundary with INVERT on the stencil wherever it is in front of the scene
// (depth pass), then draw the scene once more with the light off where the bit is set.
//
// One bit counts only parity, so the boundary must be the boundary of the union of all
// volumes. The lesson builds it exactly for what it can: one convex caster (its silhouette),
// a planar cut-out (its outline and holes). Two casters whose volumes overlap, and an eye
// inside a volume, show where parity breaks.

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/shadow_volume.h"
#include "geometry/shapes.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/light_marker.h"
#include "gl/light_shading.h"
#include "gl/shader.h"

using namespace stencil;

namespace {

constexpr glm::vec4 kLight{1.6f, 5.0f, 1.2f, 1.0f};  // a point light, still; the casters turn
constexpr glm::vec3 kAmbient{0.25f};
constexpr glm::vec3 kLightColour{1.2f, 1.15f, 1.0f};
constexpr glm::vec4 kMarkerColour{1.0f, 0.95f, 0.7f, 1.0f};

struct Object {
  const Mesh* mesh;
  const GpuMesh* gpu;
  glm::mat4 model;
  glm::vec3 colour;
  bool twoSided;  // the cut-out is seen from both sides: no culling
};

class InvertShadowVolumes final : public Lesson {
 public:
  InvertShadowVolumes()
      : light_("common/light.vert", "common/light.frag"),
        volume_("common/volume.vert", "common/flat.frag"),
        groundMesh_(makePlane(3.0f)),
        cubeMesh_(makeCube(0.45f)),
        ballMesh_(makeSphere(0.35f, 16, 8)),
        frameMesh_(makeSquareRing(0.6f, 0.3f)),
        ground_(groundMesh_),
        cube_(cubeMesh_),
        ball_(ballMesh_),
        frame_(frameMesh_),
        cubeCaster_(prepareCaster(cubeMesh_)),
        ballCaster_(prepareCaster(ballMesh_)),
        frameCaster_(prepareCaster(frameMesh_)) {}

  void render(Frame& f) override {
    glClearColor(0.1f, 0.1f, 0.13f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    const std::vector<Object> scene = sceneAt(f);

    // 1. The scene with the light on, filling the depth buffer.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_STENCIL_TEST);
    drawScene(f, scene, kLightColour);
    marker_.draw(f.projection * f.view, glm::vec3(kLight), kMarkerColour);
    f.pass("lit");
    if (!f.on("shadow")) return;

    // 2. The volumes' faces flip one bit wherever they lie in front of the scene.
    std::vector<const GpuTriangles*> volumes = buildVolumes(f);
    glEnable(GL_STENCIL_TEST);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // the stencil only
    glDepthMask(GL_FALSE);                                // the volumes are not surfaces
    glDisable(GL_CULL_FACE);                              // front and back faces both cross
    glStencilFunc(GL_ALWAYS, 0, 0x01);
    glStencilMask(0x01);                       // one bit
    glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);  // depth pass: a crossing between eye and scene
    drawVolumes(f, volumes, glm::vec4(0));
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    f.pass("volumes");

    // 3. The scene again without the light, only where the bit says "odd: in shadow".
    glDepthFunc(GL_EQUAL);                // exactly the visible surfaces of pass 1
    glStencilFunc(GL_EQUAL, 0x01, 0x01);  // the shadowed pixels
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    drawScene(f, scene, glm::vec3(0));
    glDepthFunc(GL_LESS);
    f.pass("unlit");

    if (f.on("show")) {  // the volumes as translucent sheets, for the classroom
      glDisable(GL_STENCIL_TEST);
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      drawVolumes(f, volumes, glm::vec4(1.0f, 0.85f, 0.2f, 0.18f));
      glDisable(GL_BLEND);
      f.pass("show-volumes");
    }
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
  }

 private:
  std::vector<Object> sceneAt(const Frame& f) const {
    const float t = static_cast<float>(f.time);
    std::vector<Object> scene;
    scene.push_back({&groundMesh_, &ground_, glm::mat4(1), {0.75f, 0.75f, 0.7f}, false});
    const glm::mat4 wall =
        glm::rotate(glm::translate(glm::mat4(1), {0, 3, -3}), glm::radians(90.0f), {1, 0, 0});
    scene.push_back({&groundMesh_, &ground_, wall, {0.7f, 0.68f, 0.65f}, false});
    const int casters = f.option("casters");
    if (casters & 1) {
      glm::mat4 m = glm::rotate(glm::translate(glm::mat4(1), {0, 1.7f, 0}), 0.5f * t, {0, 1, 0});
      if (f.on("cutout"))  // upright, turning slowly about its vertical axis
        scene.push_back({&frameMesh_,
                         &frame_,
                         glm::rotate(m, glm::radians(70.0f), {1, 0, 0}),
                         {0.35f, 0.55f, 0.85f},
                         true});
      else
        scene.push_back({&cubeMesh_, &cube_, glm::rotate(m, 0.6f, {1, 0, 1}), {0.9f, 0.45f, 0.2f}, false});
    }
    if (casters & 2)  // between the light and the cube, a little to the side
      scene.push_back(
          {&ballMesh_, &ball_, glm::translate(glm::mat4(1), {0.95f, 3.2f, 0.3f}), {0.3f, 0.7f, 0.4f}, false});
    return scene;
  }

  bool isCaster(const Object& o) const { return o.mesh != &groundMesh_; }

  const PreparedCaster& casterFor(const Object& o) const {
    if (o.mesh == &cubeMesh_) return cubeCaster_;
    if (o.mesh == &ballMesh_) return ballCaster_;
    return frameCaster_;
  }

  // Each caster's volume built on the CPU from its silhouette as seen from the light, in the
  // caster's own space, extruded to infinity (w = 0).
  std::vector<const GpuTriangles*> buildVolumes(const Frame& f) {
    std::vector<const GpuTriangles*> built;
    volumeModels_.clear();
    std::size_t i = 0;
    for (const Object& o : sceneAt(f)) {
      if (!isCaster(o)) continue;
      const PreparedCaster& c = casterFor(o);
      const glm::vec4 light = glm::inverse(o.model) * kLight;
      volumeGpu_[i].upload(silhouetteVolume(c, light, kInfinity).vertices);
      volumeModels_.push_back(o.model);
      built.push_back(&volumeGpu_[i++]);
    }
    return built;
  }

  void drawVolumes(const Frame& f, const std::vector<const GpuTriangles*>& volumes, glm::vec4 colour) {
    volume_.set("colour", colour);
    for (std::size_t i = 0; i < volumes.size(); ++i) {
      volume_.set("transform", f.projection * f.view * volumeModels_[i]);
      volumes[i]->draw();
    }
  }

  void drawScene(const Frame& f, const std::vector<Object>& scene, glm::vec3 lightColour) {
    setLightShading(light_, {.viewProjection = f.projection * f.view,
                             .eye = f.eye,
                             .light = kLight,
                             .lightColour = lightColour,
                             .ambient = kAmbient});
    for (const Object& o : scene) {
      if (o.twoSided)
        glDisable(GL_CULL_FACE);  // the cut-out has no back to hide
      else
        glEnable(GL_CULL_FACE);  // closed objects and one-sided walls: back faces never show
      light_.set("model", o.model);
      light_.set("colour", o.colour);
      o.gpu->draw();
    }
    glDisable(GL_CULL_FACE);
  }

  Program light_, volume_;
  Mesh groundMesh_, cubeMesh_, ballMesh_, frameMesh_;
  GpuMesh ground_, cube_, ball_, frame_;
  LightMarker marker_;
  PreparedCaster cubeCaster_, ballCaster_, frameCaster_;
  GpuTriangles volumeGpu_[2];
  std::vector<glm::mat4> volumeModels_;

  // ---- test hooks ---------------------------------------------------------------------------------

 public:
  // Every visible object receives; the cut-out only casts, since one layer has no inside that
  // a ray to the light could cross (its dark side counts as in its volume, the ray cast's as lit).
  std::optional<ShadowCheck> shadowCheck(const Frame& f) const override {
    if (!f.on("shadow")) return std::nullopt;
    ShadowCheck check{{}, kLight, [](std::uint8_t s) { return (s & 0x01) == 0; }, true};
    for (const Object& o : sceneAt(f)) check.objects.push_back({o.mesh, o.model, isCaster(o), !o.twoSided});
    return check;
  }
};

// ---- the lesson: options, variants, cameras ------------------------------------------------------

// Inside the cube's shadow, between the cube and the ground, looking down at the shadow's far
// end on the ground and the lit ground around it.
OrbitCamera eyeInShadow() {
  return {.target = {-1.6f, 0.0f, -1.8f},
          .distance = 1.95f,
          .azimuthDeg = 37.8f,
          .elevationDeg = 21.0f,
          .fovyDeg = 70.0f};
}

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "07-shadow-volumes-invert";
  info.title = "Shadow volumes with an inverted bit";
  info.summary =
      "The lit scene, then the shadow volume's faces inverting one stencil bit where they are in front\n"
      "of the scene, then the scene without the light where the bit is set; where parity breaks.";
  info.stencilBits = 1;  // one bit is all the method uses
  info.options = {
      {"casters", 'C', "which casters: 1 the cube, 2 the ball above it, 3 both (their volumes overlap)", 1,
       3},
      {"cutout", 'U', "a window frame with a hole instead of the cube", 0},
      {"shadow", 'H', "draw the volumes at all (off: everything lit)", 1},
      {"show", 'X', "draw the shadow volumes translucently over the result", 0},
  };
  info.variants = {
      {"convex", "a convex cube: its silhouette bounds the volume exactly", {}},
      {"cutout", "a window frame: its outline and its hole extruded", {{"cutout", 1}}},
      {"show-volumes", "the convex cube with its volume drawn translucently", {{"show", 1}}},
      {"overlap",
       "two convex casters: where their volumes overlap the parity is even, the shadow lit",
       {{"casters", 3}}},
      {"eye-inside",
       "the eye inside the cube's shadow: every crossing count is off by one, shadows invert",
       {},
       {},
       eyeInShadow()},
  };
  info.shadows = true;
  info.passes = {"lit", "volumes", "unlit", "show-volumes"};
  info.camera = {
      .target = {-0.3f, 0.7f, -0.7f}, .distance = 7.5f, .azimuthDeg = 35.0f, .elevationDeg = 32.0f};
  return info;
}

}  // namespace

int main(int argc, char** argv) {
  return runLesson(
      lessonInfo(), [] { return std::make_unique<InvertShadowVolumes>(); }, argc, argv);
}
