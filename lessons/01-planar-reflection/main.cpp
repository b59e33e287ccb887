// Lesson 01: planar reflection without the stencil (Kilgard, "Improving Shadows and
// Reflections via the Stencil Buffer", section 2 and appendix A).
//
// A flat mirror shows the scene mirrored through its plane. Draw the scene once through the
// reflection matrix of the plane (appendix A: any plane, not only z = 0), with the cull face
// flipped because a reflection turns every winding over; then draw the mirror's surface into
// the depth buffer, so nothing of the reflection can show in front of it; then the real scene.
//
// That is all it takes when the mirror is constrained: a polished floor under everything,
// seen only from above, covers the whole reflection. A free-standing mirror is not: the
// reflection is drawn everywhere, so it leaks past the mirror's edges wherever the real scene
// does not happen to cover it, and whatever stands behind the mirror is reflected to the
// front, where it appears. Lesson 02 fixes both with the stencil and a clip plane.

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/planar.h"
#include "geometry/shapes.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/shader.h"

using namespace stencil;

namespace {

constexpr glm::vec4 kSky{0.55f, 0.65f, 0.8f, 1.0f};
constexpr glm::vec4 kLight{1.5f, 4.5f, 2.5f, 1.0f};
constexpr GLint kMirrorDrawn = 1;
constexpr float kAboveFloor = 0.01f;  // world units: a base this far up reflects this far down  // not used
                                      // by the algorithm: a record of where the mirror is

// The free-standing mirror: standing on the floor at z = -1.5, leaning back 8 degrees and
// turned 20 degrees about the vertical, so its plane is no coordinate plane.
struct StandingMirror {
  glm::mat4 place = glm::rotate(
      glm::rotate(glm::translate(glm::mat4(1), {0.0f, 0.0f, -1.5f}), glm::radians(20.0f), glm::vec3(0, 1, 0)),
      glm::radians(-8.0f), glm::vec3(1, 0, 0));
  float halfWidth = 0.8f, halfHeight = 0.55f;

  glm::vec3 normal() const { return glm::normalize(glm::vec3(place * glm::vec4(0, 0, 1, 0))); }
  glm::vec4 plane() const { return planeFrom(glm::vec3(place[3]), normal()); }
  // makePlane's square (y = 0, facing +y) stood up in the mirror's frame, winding kept.
  glm::mat4 glassModel() const {
    return place * glm::mat4(glm::vec4(halfWidth, 0, 0, 0), glm::vec4(0, 0, 1, 0),
                             glm::vec4(0, -halfHeight, 0, 0), glm::vec4(0, halfHeight + 0.1f, 0, 1));
  }
  glm::mat4 frameModel() const {  // a thin box just behind the glass: frame and back
    return place * glm::translate(glm::mat4(1), {0.0f, halfHeight + 0.1f, -0.035f}) *
           glm::scale(glm::mat4(1), {halfWidth + 0.07f, halfHeight + 0.07f, 0.03f});
  }
};

class PlanarReflection final : public Lesson {
 public:
  PlanarReflection()
      : light_("common/light.vert", "common/light.frag"),
        floor_(makePlane(3.0f, 1)),
        glass_(makePlane(1.0f, 1)),
        box_(makeCube(1.0f)),
        torus_(makeTorus(0.5f, 0.17f, 40, 20)),
        sphere_(makeSphere(0.35f, 32, 16)),
        cone_(makeCone(0.3f, 0.7f, 32)) {}

  void render(Frame& f) override {
    const bool standing = f.option("mirror") == 1;
    const glm::vec4 plane = standing ? mirror_.plane() : planeFrom({0, 0, 0}, {0, 1, 0});
    const glm::mat4 reflect = reflectionMatrix(plane);  // appendix A, for any plane

    glClearColor(kSky.r, kSky.g, kSky.b, kSky.a);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);  // nearer surfaces hide farther ones
    glEnable(GL_CULL_FACE);   // closed objects, one-sided floor and glass: back faces never show

    // ---- 1 the reflection: the scene through the plane, everywhere ----------------------------
    if (f.on("reflect")) {
      if (f.on("flip")) glFrontFace(GL_CW);           // det = -1: the mirrored front faces wind clockwise
      drawScene(f, reflect, /*withFloor=*/standing);  // a floor mirror does not reflect itself
      f.count("scene_renderings");
      glFrontFace(GL_CCW);
    }
    f.pass("reflection");

    // ---- 2 the mirror's surface into depth ------------------------------------------------------
    // Nearer than every reflected point (they lie behind the plane), so it hides the
    // reflection's depth: the real scene drawn next is tested against the mirror instead.
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, kMirrorDrawn, 0xFF);  // only a record for the stencil view and the
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);     // tests: nothing below reads it
    if (standing) {
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // a perfect mirror: depth only
      drawLit(f, glass_, mirror_.glassModel(), {0.16f, 0.2f, 0.24f}, 96.0f, glm::mat4(1));
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    } else {
      glEnable(GL_BLEND);  // a polished floor: its own colour over the reflection
      glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
      glBlendColor(0.0f, 0.0f, 0.0f, f.on("reflect") ? 0.6f : 1.0f);  // without a reflection: opaque
      drawLit(f, floor_, glm::mat4(1), {0.72f, 0.7f, 0.62f}, 16.0f, glm::mat4(1));
      glDisable(GL_BLEND);
    }
    glDisable(GL_STENCIL_TEST);
    f.pass("mirror");

    // ---- 3 the real scene ----------------------------------------------------------------------
    drawScene(f, glm::mat4(1), /*withFloor=*/standing);
    f.count("scene_renderings");
    glDisable(GL_CULL_FACE);
    f.pass("scene");
  }

 private:
  void drawLit(const Frame& f, const GpuMesh& mesh, const glm::mat4& model, glm::vec3 colour, float shininess,
               const glm::mat4& reflect) const {
    light_.set("viewProjection", f.projection * f.view);
    light_.set("light", reflect * kLight);  // lit as in the real world, then mirrored with it
    light_.set("lightColour", glm::vec3(1.1f, 1.05f, 1.0f));
    light_.set("ambient", glm::vec3(0.3f));
    light_.set("eye", f.eye);
    light_.set("model", reflect * model);
    light_.set("colour", colour);
    light_.set("shininess", shininess);
    mesh.draw();
  }

  // The objects; with the free-standing mirror also the floor, the mirror's frame, and a box
  // behind the mirror that the camera cannot see directly.
  void drawScene(const Frame& f, const glm::mat4& reflect, bool standing) const {
    const float t = static_cast<float>(f.time);
    glm::mat4 torus = glm::translate(glm::mat4(1), {0.0f, 0.9f, 0.3f});
    torus = glm::rotate(glm::rotate(torus, 0.6f * t, {0, 1, 0}), 1.1f + 0.4f * t, {1, 0, 0.3f});
    drawLit(f, torus_, torus, {0.9f, 0.45f, 0.2f}, 48.0f, reflect);
    drawLit(f, sphere_, glm::translate(glm::mat4(1), {1.1f, 0.35f, 1.0f}), {0.25f, 0.45f, 0.9f}, 64.0f,
            reflect);
    // The cone's base stands a hair above the floor: a base in the floor's plane would reflect onto
    // the plane itself, where the floor's depth test against it is a toss-up (a spiky hole).
    drawLit(f, cone_, glm::translate(glm::mat4(1), {-1.2f, 0.35f + kAboveFloor, 0.6f}), {0.85f, 0.2f, 0.25f},
            32.0f, reflect);
    if (!standing) return;
    drawLit(f, floor_, glm::mat4(1), {0.72f, 0.7f, 0.62f}, 16.0f, reflect);
    const bool reflected = reflect != glm::mat4(1);
    if (!reflected)  // the mirror's own frame is behind its glass: a mirror never shows itself
      drawLit(f, box_, mirror_.frameModel(), {0.35f, 0.25f, 0.2f}, 16.0f, reflect);
    drawLit(f, box_,
            glm::translate(glm::mat4(1), {0.3f, 0.3f, -2.6f}) * glm::scale(glm::mat4(1), glm::vec3(0.3f)),
            {0.6f, 0.3f, 0.75f}, 32.0f, reflect);
  }

  Program light_;
  GpuMesh floor_, glass_, box_, torus_, sphere_, cone_;
  StandingMirror mirror_;
};

// ---- the lesson: options, variants, camera -------------------------------------------------------

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "01-planar-reflection";
  info.title = "Planar reflection without the stencil";
  info.summary =
      "The scene drawn through a plane's reflection matrix with the cull face flipped, the mirror into\n"
      "depth, then the scene: right for a polished floor, leaking for a free-standing mirror.";
  info.options = {
      {"mirror", 'M', "0 a polished floor under the scene (constrained), 1 a free-standing tilted mirror", 0,
       1},
      {"reflect", 'E', "draw the reflection at all (off: the reference the tests compare with)", 1},
      {"flip", 'L', "flip the cull face for the reflection (off: the reflection turns inside out)", 1},
  };
  info.variants = {
      {"floor", "a polished floor: the reflection stays under the floor, as it should", {}},
      {"free-standing",
       "a free-standing mirror: the reflection leaks past its edges, and what stands behind it appears",
       {{"mirror", 1}}},
  };
  info.passes = {"reflection", "mirror", "scene"};
  info.camera.distance = 7.5f;
  info.camera.azimuthDeg = 30.0f;
  info.camera.elevationDeg = 28.0f;
  info.camera.target = {0.0f, 0.6f, -0.4f};
  return info;
}

}  // namespace

int main(int argc, char** argv) {
  return runLesson(
      lessonInfo(), [] { return std::make_unique<PlanarReflection>(); }, argc, argv);
}
