// A small lesson that renders scenes from files, for testing what runSceneLesson gives a lesson
// (--scene, the scene's camera, --mask-out) and the scene oracle. Its shadows are the plainest
// robust kind there is: every triangle of every caster, whichever way it faces, gets its own
// closed volume (sides, the triangle as the light cap, the triangle pushed to infinity as the dark
// cap), counted z-fail with wrapping operations, the volumes pushed back by a polygon offset so a
// cap on a visible surface counts as behind it. Slow, but right for open meshes too, as long as
// no count reaches 256. Variant z-pass counts the faces in front instead (Kilgard's z-pass), to
// show that the hard-case files of the eye in a volume and the near plane cutting one break it. Not right
// everywhere on the casters themselves: the offset also pushes a volume's side behind a visible face nearly
// in its plane (a face almost edge-on to the light).
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/shadow_volume.h"
#include "geometry/shapes.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/light_shading.h"
#include "gl/shader.h"

using namespace stencil;

namespace {

// Without --scene: a ground and a box under a point light.
Scene builtInScene() {
  Scene scene;
  scene.camera.eye = {4.0f, 4.0f, 6.0f};
  scene.camera.nearPlane = 0.5f;
  scene.lights.push_back({.position = {1.5f, 4.0f, -0.8f, 1.0f}, .colour = glm::vec3(1.0f)});
  scene.objects.push_back(sceneObject("ground", makePlane(4.0f), glm::mat4(1.0f), glm::vec3(0.8f), false));
  scene.objects.push_back(sceneObject("box", makeCube(0.5f),
                                      glm::translate(glm::mat4(1.0f), {0.0f, 1.0f, 0.0f}), glm::vec3(0.8f)));
  return scene;
}

// The triangles' own volumes, closed, in object space.
std::vector<glm::vec4> triangleVolumes(const Mesh& caster, const glm::vec4& light) {
  std::vector<glm::vec4> out = polygonVolumes(caster, light, kInfinity, /*twoSided=*/true).vertices;
  const std::vector<bool> lit = facesLight(caster, light);
  for (std::size_t t = 0; t < caster.triangleCount(); ++t) {
    glm::vec3 p[3];
    for (int k = 0; k < 3; ++k) p[k] = caster.positions[caster.indices[3 * t + k]];
    if (!lit[t]) std::swap(p[1], p[2]);  // walked so it faces the light, as polygonVolumes does
    for (int k = 0; k < 3; ++k) out.emplace_back(p[k], 1.0f);
    for (int k = 2; k >= 0; --k) out.push_back(extrudeAway(p[k], light, kInfinity));
  }
  return out;
}

class SceneLesson : public Lesson {
 public:
  explicit SceneLesson(const Scene* fromFile)
      : owned_(fromFile ? Scene{} : builtInScene()),
        scene_(fromFile ? *fromFile : owned_),
        shaded_("common/light.vert", "common/light.frag"),
        volume_("common/volume.vert", "common/flat.frag") {
    for (const SceneObject& o : scene_.objects) meshes_.emplace_back(o.mesh);
  }

  void render(Frame& frame) override {
    frame.count("scene_objects", scene_.objects.size());
    frame.count("scene_lights", scene_.lights.size());
    const glm::mat4 viewProjection = frame.projection * frame.view;
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    // Depth and the ambient colour of everything.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    drawObjects(frame, viewProjection, glm::vec4(0.0f, 1.0f, 0.0f, 0.0f), scene_.ambient, glm::vec3(0.0f));
    frame.pass("ambient");

    for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
      const SceneLight& light = scene_.lights[i];
      glClear(GL_STENCIL_BUFFER_BIT);
      // z-fail: count the volumes' faces behind the visible surface; colour and depth untouched.
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
      glDepthMask(GL_FALSE);
      glEnable(GL_STENCIL_TEST);
      glStencilFunc(GL_ALWAYS, 0, 0xFF);
      // z-pass (variant z-pass) counts the faces in front of the visible surface, where the depth
      // test passes: a front face enters a volume (up), a back face leaves one (down). z-fail counts
      // those behind it, where the test fails, the other way round.
      const bool zpass = frame.on("zpass");
      const GLenum front = zpass ? GL_INCR_WRAP : GL_DECR_WRAP, back = zpass ? GL_DECR_WRAP : GL_INCR_WRAP;
      glStencilOpSeparate(GL_FRONT, GL_KEEP, zpass ? GL_KEEP : front, zpass ? front : GL_KEEP);
      glStencilOpSeparate(GL_BACK, GL_KEEP, zpass ? GL_KEEP : back, zpass ? back : GL_KEEP);
      if (!zpass) glEnable(GL_DEPTH_CLAMP);  // the dark caps lie at infinity, beyond a finite far plane
      // A light cap lies on its caster's surface: pushed back a little, it always counts as behind
      // it (whichever shader computed which depth), so a lit surface does not shadow itself.
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(1.0f, 1.0f);
      for (const SceneObject& o : scene_.objects) {
        if (!o.casts) continue;
        const glm::mat4 model = o.modelAt(frame.time);
        const glm::vec4 objectLight = glm::inverse(model) * light.position;
        volumes_.upload(triangleVolumes(o.caster.mesh, objectLight));
        volume_.use();
        volume_.set("transform", viewProjection * model);
        volumes_.draw();
      }
      glDisable(GL_POLYGON_OFFSET_FILL);
      glDisable(GL_DEPTH_CLAMP);
      frame.pass("volumes");
      frame.shadowMask("light-" + std::to_string(i));

      // The light adds where the count is zero, on the surfaces the depth pass kept.
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      glStencilFunc(GL_EQUAL, 0, 0xFF);
      glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
      glDepthFunc(GL_EQUAL);
      glEnable(GL_BLEND);
      glBlendFunc(GL_ONE, GL_ONE);
      drawObjects(frame, viewProjection, light.position, glm::vec3(0.0f), light.colour);
      glDisable(GL_BLEND);
      glDepthFunc(GL_LESS);
      glDepthMask(GL_TRUE);
      glDisable(GL_STENCIL_TEST);
      frame.pass("light");
    }
  }

  std::optional<ShadowCheck> shadowCheck(const Frame& frame) const override {
    ShadowCheck check;
    check.objects = oracleObjects(scene_, frame.time);
    check.light = scene_.lights.back().position;  // the stencil holds the last light's shadow
    check.lightRadius = scene_.lights.back().radius;
    check.litInStencil = [](std::uint8_t s) { return s == 0; };
    check.judgeReceiversOnly = true;
    return check;
  }

 private:
  void drawObjects(Frame& frame, const glm::mat4& viewProjection, const glm::vec4& light,
                   const glm::vec3& ambient, const glm::vec3& lightColour) {
    setLightShading(shaded_, {.viewProjection = viewProjection,
                              .eye = frame.eye,
                              .light = light,
                              .lightColour = lightColour,
                              .ambient = ambient});
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
      const SceneObject& o = scene_.objects[i];
      shaded_.set("model", o.modelAt(frame.time));
      shaded_.set("colour", o.colour);
      meshes_[i].draw();
    }
  }

  Scene owned_;
  const Scene& scene_;
  Program shaded_, volume_;
  std::vector<GpuMesh> meshes_;
  GpuTriangles volumes_;
};

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "99-scene-test";
  info.title = "Scene test lesson";
  info.summary = "Renders a scene file with per-triangle z-fail volumes (tests only).";
  info.options = {{"zpass", 'Z', "count z-pass (off: z-fail)", 0}};
  info.variants = {
      {"z-fail", "every light's shadow, counted z-fail", {}},
      {"z-pass", "counted z-pass: wrong with the eye in a volume or the near plane in one", {{"zpass", 1}}}};
  info.shadows = true;
  info.passes = {"ambient", "volumes", "light"};
  info.camera = orbitCameraOf(builtInScene().camera);
  return info;
}

}  // namespace

int main(int argc, char** argv) {
  return runSceneLesson(
      lessonInfo(), [](const Scene* fromFile) { return std::make_unique<SceneLesson>(fromFile); }, argc,
      argv);
}
