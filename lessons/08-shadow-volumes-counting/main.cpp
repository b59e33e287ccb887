// Lesson 08: counting shadow volumes (Kilgard, "Improving Shadows and Reflections via the
// Stencil Buffer", section 6.3 and appendix C).
//
// Lesson 07's single bit counts crossings modulo 2, so two overlapping volumes cancel. Count
// instead: the stencil goes up by one for every front face of a volume in front of the visible
// surface (the ray enters a volume) and down by one for every back face (it leaves one). A
// nonzero count means the surface is inside at least one volume. Overlaps now add up, so each
// caster, or even each triangle, may bring its own volume: Kilgard's extendVolume extrudes
// every triangle that faces the light, no silhouette and no adjacency needed.
//
// It still assumes the eye is outside every volume, and that nothing clips a volume between
// the eye and the surface: the eye inside a volume and the near plane cutting one both break
// the count. And the order of INCR and DECR matters once the stencil saturates.

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

constexpr glm::vec3 kAmbient{0.25f};
constexpr glm::vec3 kLightColour{1.2f, 1.15f, 1.0f};
constexpr glm::vec4 kMarkerColour{1.0f, 0.95f, 0.7f, 1.0f};

struct Object {
  const Mesh* mesh;
  const GpuMesh* gpu;
  glm::mat4 model;
  glm::vec3 colour;
};

class CountingShadowVolumes final : public Lesson {
 public:
  CountingShadowVolumes()
      : light_("common/light.vert", "common/light.frag"),
        volume_("common/volume.vert", "common/flat.frag"),
        groundMesh_(makePlane(3.0f)),
        cubeMesh_(makeCube(0.45f)),
        torusMesh_(makeTorus(0.5f, 0.17f, 32, 12)),
        ballMesh_(makeSphere(0.35f, 16, 8)),
        ground_(groundMesh_),
        cube_(cubeMesh_),
        torus_(torusMesh_),
        ball_(ballMesh_),
        cubeCaster_(prepareCaster(cubeMesh_)),
        torusCaster_(prepareCaster(torusMesh_)),
        ballCaster_(prepareCaster(ballMesh_)) {}

  void render(Frame& f) override {
    glClearColor(0.1f, 0.1f, 0.13f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    const std::vector<Object> scene = sceneAt(f);
    const glm::vec4 light = lightAt(f);

    // 1. The scene with the light on, filling the depth buffer.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_CULL_FACE);  // every object is closed, or a wall seen from its front
    drawScene(f, scene, light, kLightColour);
    marker_.draw(f.projection * f.view, glm::vec3(light), kMarkerColour);
    f.pass("lit");
    if (!f.on("shadow")) {
      glDisable(GL_CULL_FACE);
      return;
    }

    // 2. Count the volume faces in front of the scene: +1 entering through a front face,
    //    -1 leaving through a back face. Two passes, culling the other side each time.
    buildVolumes(f, scene, light);
    const bool wrap = f.on("wrap");
    const GLenum up = wrap ? GL_INCR_WRAP : GL_INCR, down = wrap ? GL_DECR_WRAP : GL_DECR;
    glEnable(GL_STENCIL_TEST);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // the stencil only
    glDepthMask(GL_FALSE);                                // the volumes are not surfaces
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    const bool backFirst = f.on("back-first");
    for (int step = 0; step < 2; ++step) {
      if ((step == 0) != backFirst) {
        glCullFace(GL_BACK);                // front faces only:
        glStencilOp(GL_KEEP, GL_KEEP, up);  // in front of the scene, the ray enters a volume
        drawVolumes(f, glm::vec4(0));
        f.pass("front-faces");
      } else {
        glCullFace(GL_FRONT);                 // back faces only:
        glStencilOp(GL_KEEP, GL_KEEP, down);  // in front of the scene, the ray leaves a volume
        drawVolumes(f, glm::vec4(0));
        f.pass("back-faces");
      }
    }
    glCullFace(GL_BACK);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    // 3. The scene again without the light where the count is not zero.
    glDepthFunc(GL_EQUAL);                // exactly the visible surfaces of pass 1
    glStencilFunc(GL_NOTEQUAL, 0, 0xFF);  // inside at least one volume
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    drawScene(f, scene, light, glm::vec3(0));
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    f.pass("unlit");

    if (f.on("show")) {  // the volumes as translucent sheets, for the classroom
      glDisable(GL_STENCIL_TEST);
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      drawVolumes(f, glm::vec4(1.0f, 0.85f, 0.2f, 0.12f));
      glDisable(GL_BLEND);
      f.pass("show-volumes");
    }
    glDepthMask(GL_TRUE);
  }

 private:
  static glm::vec4 lightAt(const Frame& f) {
    return f.on("near-light") ? glm::vec4(0.5f, 2.9f, 0.4f, 1.0f) : glm::vec4(1.6f, 5.0f, 1.2f, 1.0f);
  }

  // Lesson 07's scene with both casters: a ground, a back wall, a turning cube (or torus) and a
  // ball between it and the light, whose volumes overlap.
  std::vector<Object> sceneAt(const Frame& f) const {
    const float t = static_cast<float>(f.time);
    std::vector<Object> scene;
    scene.push_back({&groundMesh_, &ground_, glm::mat4(1), {0.75f, 0.75f, 0.7f}});
    const glm::mat4 wall =
        glm::rotate(glm::translate(glm::mat4(1), {0, 3, -3}), glm::radians(90.0f), {1, 0, 0});
    scene.push_back({&groundMesh_, &ground_, wall, {0.7f, 0.68f, 0.65f}});
    const glm::mat4 m = glm::rotate(glm::translate(glm::mat4(1), {0, 1.7f, 0}), 0.5f * t, {0, 1, 0});
    if (f.on("torus"))
      scene.push_back({&torusMesh_, &torus_, glm::rotate(m, 1.1f, {1, 0, 0}), {0.85f, 0.4f, 0.5f}});
    else
      scene.push_back({&cubeMesh_, &cube_, glm::rotate(m, 0.6f, {1, 0, 1}), {0.9f, 0.45f, 0.2f}});
    if (!f.on("near-light"))  // the near light sits where the ball would be
      scene.push_back(
          {&ballMesh_, &ball_, glm::translate(glm::mat4(1), {0.95f, 3.2f, 0.3f}), {0.3f, 0.7f, 0.4f}});
    return scene;
  }

  bool isCaster(const Object& o) const { return o.mesh != &groundMesh_; }

  const PreparedCaster& casterFor(const Object& o) const {
    if (o.mesh == &cubeMesh_) return cubeCaster_;
    if (o.mesh == &torusMesh_) return torusCaster_;
    return ballCaster_;
  }

  // The volumes, in each caster's own space: per lit triangle (extendVolume) or from the
  // silhouette, to infinity or to the chosen length.
  void buildVolumes(const Frame& f, const std::vector<Object>& scene, glm::vec4 worldLight) {
    const float distance = f.option("extrusion") == 0 ? kInfinity : static_cast<float>(f.option("extrusion"));
    volumeModels_.clear();
    std::size_t i = 0;
    for (const Object& o : scene) {
      if (!isCaster(o)) continue;
      const PreparedCaster& c = casterFor(o);
      const glm::vec4 light = glm::inverse(o.model) * worldLight;
      volumeGpu_[i++].upload(f.on("silhouette") ? silhouetteVolume(c, light, distance).vertices
                                                : polygonVolumes(*o.mesh, light, distance).vertices);
      volumeModels_.push_back(o.model);
    }
  }

  void drawVolumes(const Frame& f, glm::vec4 colour) {
    volume_.set("colour", colour);
    for (std::size_t i = 0; i < volumeModels_.size(); ++i) {
      volume_.set("transform", f.projection * f.view * volumeModels_[i]);
      volumeGpu_[i].draw();
    }
  }

  void drawScene(const Frame& f, const std::vector<Object>& scene, glm::vec4 light, glm::vec3 lightColour) {
    setLightShading(light_, {.viewProjection = f.projection * f.view,
                             .eye = f.eye,
                             .light = light,
                             .lightColour = lightColour,
                             .ambient = kAmbient});
    for (const Object& o : scene) {
      light_.set("model", o.model);
      light_.set("colour", o.colour);
      o.gpu->draw();
    }
  }

  Program light_, volume_;
  Mesh groundMesh_, cubeMesh_, torusMesh_, ballMesh_;
  GpuMesh ground_, cube_, torus_, ball_;
  LightMarker marker_;
  PreparedCaster cubeCaster_, torusCaster_, ballCaster_;
  GpuTriangles volumeGpu_[2];
  std::vector<glm::mat4> volumeModels_;

  // ---- test hooks ---------------------------------------------------------------------------------

 public:
  // Every visible object receives, the casters included (their dark sides lie in their own
  // volume). A count of zero is lit.
  std::optional<ShadowCheck> shadowCheck(const Frame& f) const override {
    if (!f.on("shadow")) return std::nullopt;
    ShadowCheck check{{}, lightAt(f), [](std::uint8_t s) { return s == 0; }, true};
    for (const Object& o : sceneAt(f)) check.objects.push_back({o.mesh, o.model, isCaster(o), true});
    return check;
  }
};

// ---- the lesson: options, variants, cameras ------------------------------------------------------

// Lesson 07's eye inside the cube's shadow.
OrbitCamera eyeInShadow() {
  return {.target = {-1.6f, 0.0f, -1.8f},
          .distance = 1.95f,
          .azimuthDeg = 37.8f,
          .elevationDeg = 21.0f,
          .fovyDeg = 70.0f};
}

// Just outside the side of the cube's shadow, looking down along it, with a near plane far
// enough out that it cuts through the volume's side face.
OrbitCamera nearPlaneInVolume() {
  return {.target = {-0.82f, 0.0f, -0.62f},
          .distance = 1.5f,
          .azimuthDeg = -18.3f,
          .elevationDeg = 27.9f,
          .fovyDeg = 70.0f,
          .nearPlane = 1.0f};
}

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "08-shadow-volumes-counting";
  info.title = "Counting shadow volumes";
  info.summary =
      "Front faces of the volumes INCR, back faces DECR, a nonzero count is a shadow: overlapping\n"
      "volumes add up, so every lit triangle may extrude its own; where the count still breaks.";
  info.options = {
      {"silhouette", 'G', "one volume per caster from its silhouette (off: one per lit triangle)", 0},
      {"torus", 'T', "a torus instead of the cube: a caster whose volume overlaps itself", 0},
      {"wrap", 'W', "INCR_WRAP and DECR_WRAP (off: saturating INCR and DECR)", 1},
      {"back-first", 'B', "draw the back faces (DECR) before the front faces (INCR)", 0},
      {"near-light", 'L', "the light just above the cube", 0},
      {"extrusion", 'E', "how far the volumes reach: 0 to infinity (w = 0), else that many units", 0, 4},
      {"shadow", 'H', "draw the volumes at all (off: everything lit)", 1},
      {"show", 'X', "draw the shadow volumes translucently over the result", 0},
  };
  info.variants = {
      {"counting", "two overlapping casters, a volume per lit triangle, counted", {}},
      {"silhouette",
       "the same with one volume per caster: the same shadow, fewer fragments",
       {{"silhouette", 1}}},
      {"torus", "a torus: its own volume overlaps itself, the count takes it", {{"torus", 1}}},
      {"show-volumes", "the per-triangle volumes drawn translucently", {{"show", 1}}},
      {"wrap-back-first",
       "back faces first with wrapping operations: the count comes right",
       {{"back-first", 1}}},
      {"saturate-back-first",
       "back faces first with saturating operations: DECR at zero is lost, false shadows",
       {{"back-first", 1}, {"wrap", 0}}},
      {"near-light", "the light just above the cube, volumes to infinity", {{"near-light", 1}}},
      {"short-extrusion",
       "the same light with volumes one unit long: they end above the ground, the shadow is lost",
       {{"near-light", 1}, {"extrusion", 1}}},
      {"eye-inside",
       "the eye inside the cube's shadow: the count is off by one everywhere",
       {},
       {},
       eyeInShadow()},
      {"near-plane",
       "the near plane cuts the cube's volume: the entries it clips away are not counted",
       {},
       {},
       nearPlaneInVolume()},
  };
  info.shadows = true;
  info.passes = {"lit", "front-faces", "back-faces", "unlit", "show-volumes"};
  info.camera = {
      .target = {-0.3f, 0.7f, -0.7f}, .distance = 7.5f, .azimuthDeg = 35.0f, .elevationDeg = 32.0f};
  return info;
}

}  // namespace

int main(int argc, char** argv) {
  return runLesson(
      lessonInfo(), [] { return std::make_unique<CountingShadowVolumes>(); }, argc, argv);
}
