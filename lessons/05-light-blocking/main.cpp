// Lesson 05: shadows that block the light instead of dampening it (Kilgard, "Improving
// Shadows and Reflections via the Stencil Buffer", section 5).
//
// Lesson 04 darkens the shadowed ground by blending black over it. That dampens whatever
// the light did there, highlight and colour included, where a real shadow removes the
// light. Here the flattened caster only marks the shadowed ground in the stencil (INCR,
// colour writes off), and the ground is drawn again with the light off where the mark is.
//
// The general form handles several planar surfaces and several lights. Each surface gets
// its own tag; the scene is drawn once with ambient light only, then for each light and each
// surface: mark that light's shadow (INCR), add the light where the tag is unmarked, and
// unmark (DECR) so the tags are clean for the next light.

#include <array>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/planar.h"
#include "geometry/shapes.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/light_marker.h"
#include "gl/shader.h"

using namespace stencil;

namespace {

constexpr float kRoom = 2.5f;  // half the size of the ground and of each wall

struct Surface {
  glm::mat4 model;
  glm::vec4 plane;
  glm::vec3 colour;
  GLint tag;  // even, so tag + 1 (the shadow mark) never meets another surface's tag
};

struct Light {
  glm::vec4 position;
  glm::vec3 colour;
};

class LightBlocking final : public Lesson {
 public:
  LightBlocking()
      : light_("common/light.vert", "common/light.frag"),
        shadow_("common/projected_shadow.vert", "common/flat.frag"),
        panelMesh_(makePlane(kRoom, 1)),
        torusMesh_(makeTorus(0.7f, 0.25f, 48, 24)),
        panel_(panelMesh_),
        torus_(torusMesh_),
        marker_(0.08f, 16, 8) {
    // The ground, a back wall (z = -kRoom) and a left wall (x = -kRoom), from one square.
    const glm::mat4 back = glm::rotate(glm::translate(glm::mat4(1), {0, kRoom, -kRoom}), glm::radians(90.0f),
                                       glm::vec3(1, 0, 0));
    const glm::mat4 left = glm::rotate(glm::translate(glm::mat4(1), {-kRoom, kRoom, 0}), glm::radians(-90.0f),
                                       glm::vec3(0, 0, 1));
    surfaces_ = {{
        {glm::mat4(1), planeFrom({0, 0, 0}, {0, 1, 0}), {0.8f, 0.8f, 0.75f}, 2},
        {back, planeFrom({0, 0, -kRoom}, {0, 0, 1}), {0.75f, 0.7f, 0.65f}, 4},
        {left, planeFrom({-kRoom, 0, 0}, {1, 0, 0}), {0.7f, 0.72f, 0.78f}, 6},
    }};
  }

  void render(Frame& f) override {
    glClearColor(0.12f, 0.12f, 0.15f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    if (f.on("multi"))
      renderGeneral(f);
    else
      renderOneLight(f);
  }

 private:
  // ---- one light, one surface: the paper's first form ---------------------------------------
  void renderOneLight(Frame& f) {
    const Surface& ground = surfaces_[0];
    const Light light = lightsAt(f)[0];
    const glm::vec3 lightColour = f.on("light") ? light.colour : glm::vec3(0);

    // The whole scene fully lit, the visible ground tagged (drawn after the caster).
    glEnable(GL_CULL_FACE);  // closed caster
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    drawCaster(f, kAmbient, light.position, lightColour);
    drawMarker(f, light);
    glDisable(GL_CULL_FACE);
    glStencilFunc(GL_ALWAYS, ground.tag, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);  // only where the ground is visible
    drawSurface(f, ground, kAmbient, light.position, lightColour);
    f.pass("scene");

    if (!f.on("shadow")) return;
    glEnable(GL_CULL_FACE);                     // one layer per layer of caster is enough
    glDisable(GL_DEPTH_TEST);                   // the tag already says where the ground is visible
    glStencilFunc(GL_EQUAL, ground.tag, 0xFF);  // on tagged ground, once per pixel:
    if (f.on("block")) {
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // only mark: no colour yet
      glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);               // tag -> tag + 1 under the shadow
      drawShadow(f, ground, light.position, glm::vec4(0));
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    } else {
      glEnable(GL_BLEND);  // lesson 04: blend black over the lit ground
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);  // the first darkening clears the tag
      drawShadow(f, ground, light.position,
                 glm::vec4(0, 0, 0, 0.1f * static_cast<float>(f.option("darkness"))));
      glDisable(GL_BLEND);
    }
    glDisable(GL_CULL_FACE);
    f.pass("shadow");

    if (!f.on("block")) return;
    // The marked ground drawn again, lit by the ambient light alone: the light is blocked.
    glStencilFunc(GL_EQUAL, ground.tag + 1, 0xFF);  // only the marked pixels
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    drawSurface(f, ground, kAmbient, light.position, glm::vec3(0));  // depth test still off: the
    f.pass("unlit");                                                 // marks are on visible ground only
  }

  // ---- several surfaces, several lights: the general algorithm -------------------------------
  void renderGeneral(Frame& f) {
    // Ambient light only, each visible surface tagged with its own value.
    glEnable(GL_CULL_FACE);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    drawCaster(f, kAmbient, glm::vec4(0, 1, 0, 0), glm::vec3(0));
    const std::vector<Light> lights = lightsAt(f);
    for (const Light& l : lights) drawMarker(f, l);
    glDisable(GL_CULL_FACE);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);  // the tag of the nearest visible surface wins
    for (const Surface& s : surfaces_) {
      glStencilFunc(GL_ALWAYS, s.tag, 0xFF);
      drawSurface(f, s, kAmbient, glm::vec4(0, 1, 0, 0), glm::vec3(0));
    }
    f.pass("ambient");

    static const char* const kLightPass[] = {"light 1", "light 2", "light 3"};
    const int count = f.option("lights");
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);  // each light adds its share
    for (int i = 0; i < count; ++i) {
      const Light& light = lights[static_cast<size_t>(i)];
      if (f.on("shadow")) markShadows(light, f, GL_INCR);  // tag -> tag + 1 where this light is blocked

      // Add the light: on each surface only where the tag is unmarked; on the caster everywhere.
      glDepthMask(GL_FALSE);
      glDepthFunc(GL_EQUAL);  // only the visible surface, already in the depth buffer
      glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
      for (const Surface& s : surfaces_) {
        glStencilFunc(GL_EQUAL, s.tag, 0xFF);
        drawSurface(f, s, glm::vec3(0), light.position, f.on("light") ? light.colour : glm::vec3(0));
      }
      glStencilFunc(GL_ALWAYS, 0, 0xFF);
      glEnable(GL_CULL_FACE);
      drawCaster(f, glm::vec3(0), light.position, f.on("light") ? light.colour : glm::vec3(0));
      glDisable(GL_CULL_FACE);
      glDepthFunc(GL_LESS);
      glDepthMask(GL_TRUE);

      if (f.on("shadow")) markShadows(light, f, GL_DECR);  // tag + 1 -> tag: clean for the next light
      f.pass(kLightPass[i]);
    }
    glDisable(GL_BLEND);
  }

  // The caster flattened onto every surface, changing the stencil only: INCR turns the
  // surface's tag into the mark, DECR turns the mark back into the tag. The stencil test
  // makes each pixel change once however many layers of the caster land on it.
  void markShadows(const Light& light, const Frame& f, GLenum op) {
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDisable(GL_DEPTH_TEST);  // the tags already say where each surface is visible
    glEnable(GL_CULL_FACE);
    glStencilOp(GL_KEEP, GL_KEEP, op);
    for (const Surface& s : surfaces_) {
      glStencilFunc(GL_EQUAL, op == GL_INCR ? s.tag : s.tag + 1, 0xFF);
      drawShadow(f, s, light.position, glm::vec4(0));
    }
    glDisable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }

  // A warm light circling above for the single-light form; three coloured lights for the
  // general one, close enough to the corner that each throws a shadow on every surface.
  static std::vector<Light> lightsAt(const Frame& f) {
    const float t = static_cast<float>(f.time);
    if (!f.on("multi")) {
      const float a = 0.4f * t + 3.0f;  // behind the torus at first: its shadow falls on the highlight
      return {{{1.3f * std::cos(a), 3.0f, 1.3f * std::sin(a), 1.0f}, {1.3f, 1.2f, 1.0f}}};
    }
    // Red low on the right throws onto the left wall, blue low in front onto the back wall,
    // green high onto the ground; each circles a little.
    const std::array<Light, 3> base = {{{{1.8f, 1.7f, 0.2f, 1.0f}, {0.75f, 0.15f, 0.1f}},
                                        {{1.3f, 3.6f, 1.3f, 1.0f}, {0.15f, 0.65f, 0.2f}},
                                        {{0.2f, 1.7f, 1.9f, 1.0f}, {0.15f, 0.25f, 0.8f}}}};
    std::vector<Light> lights;
    for (size_t i = 0; i < base.size(); ++i) {
      const float a = 0.6f * t + 2.0944f * static_cast<float>(i);
      lights.push_back(
          {base[i].position + 0.3f * glm::vec4(std::cos(a), std::sin(a), std::sin(a), 0.0f), base[i].colour});
    }
    return lights;
  }

  static glm::mat4 casterModel(const Frame& f) {
    const float t = static_cast<float>(f.time);
    glm::mat4 m =
        glm::translate(glm::mat4(1), f.on("multi") ? glm::vec3(-0.2f, 1.2f, -0.2f) : glm::vec3(0, 1.1f, 0));
    m = glm::rotate(m, 0.5f * t, {0, 1, 0});
    return glm::rotate(m, 1.0f + 0.3f * t, {1, 0, 0.3f});
  }

  void setLighting(const Frame& f, glm::vec3 ambient, glm::vec4 light, glm::vec3 lightColour) {
    light_.set("viewProjection", f.projection * f.view);
    light_.set("ambient", ambient);
    light_.set("light", light);
    light_.set("lightColour", lightColour);
    light_.set("eye", f.eye);
  }

  void drawSurface(const Frame& f, const Surface& s, glm::vec3 ambient, glm::vec4 light,
                   glm::vec3 lightColour) {
    setLighting(f, ambient, light, lightColour);
    light_.set("model", s.model);
    light_.set("colour", s.colour);
    light_.set("shininess", 24.0f);  // a broad highlight, to see what a dampened shadow leaves
    panel_.draw();
  }

  void drawCaster(const Frame& f, glm::vec3 ambient, glm::vec4 light, glm::vec3 lightColour) {
    setLighting(f, ambient, light, lightColour);
    light_.set("model", casterModel(f));
    light_.set("colour", glm::vec3(0.9f, 0.45f, 0.2f));
    light_.set("shininess", 48.0f);
    torus_.draw();
  }

  void drawShadow(const Frame& f, const Surface& s, glm::vec4 light, glm::vec4 colour) {
    shadow_.set("model", casterModel(f));
    shadow_.set("shadowMatrix", planarShadowMatrix(s.plane, light));
    shadow_.set("viewProjection", f.projection * f.view);
    shadow_.set("receiver", s.plane);
    shadow_.set("light", light);
    shadow_.set("colour", colour);
    glEnable(GL_CLIP_DISTANCE0);  // the shader keeps only the caster's part between the
    glEnable(GL_CLIP_DISTANCE1);  // receiver and the light (enabled only for shaders that write them)
    torus_.draw();
    glDisable(GL_CLIP_DISTANCE0);
    glDisable(GL_CLIP_DISTANCE1);
  }

  void drawMarker(const Frame& f, const Light& l) {
    marker_.draw(f.projection * f.view, glm::vec3(l.position),
                 glm::vec4(glm::min(l.colour, glm::vec3(1.0f)), 1.0f));
  }

  static constexpr glm::vec3 kAmbient{0.3f};

  Program light_, shadow_;
  Mesh panelMesh_, torusMesh_;  // kept for the oracle's ray cast
  GpuMesh panel_, torus_;
  LightMarker marker_;
  std::array<Surface, 3> surfaces_;

  // ---- test hooks ---------------------------------------------------------------------------------

 public:
  // One light on the ground: its visible pixels keep their tag exactly where the light
  // reaches them, in both forms (INCR marks the shadow, the blended shadow ZEROes it).
  std::optional<ShadowCheck> shadowCheck(const Frame& f) const override {
    if (f.on("multi") || !f.on("shadow")) return std::nullopt;
    const Light light = lightsAt(f)[0];
    const GLint tag = surfaces_[0].tag;
    return ShadowCheck{
        {{&torusMesh_, casterModel(f), true, false},
         {&panelMesh_, surfaces_[0].model, false, true},
         {&marker_.mesh(), glm::translate(glm::mat4(1), glm::vec3(light.position)), false, false}},
        light.position,
        [tag](std::uint8_t s) { return s == tag; }};
  }
};

// ---- the lesson: options, variants, camera -------------------------------------------------------

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "05-light-blocking";
  info.title = "Shadows that block the light";
  info.summary =
      "The shadow marked in the stencil and the ground re-rendered without the light there, then the\n"
      "general algorithm: several planar surfaces, several coloured lights, ambient once.";
  info.options = {
      {"block", 'B', "block the light (on) or blend a dark shadow over it as in lesson 04 (off)", 1},
      {"multi", 'M', "three surfaces and coloured lights, the general algorithm", 0},
      {"lights", 'N', "how many coloured lights in the general algorithm", 3, 3},
      {"darkness", 'A', "tenths of the light a blended shadow takes away (block off)", 5, 10},
      {"shadow", 'H', "draw the shadows at all (off: every surface fully lit)", 1},
      {"light", 'G', "the light on (off: ambient only; with shadow off, the reference's two halves)", 1},
  };
  info.variants = {
      {"block", "the shadow blocks the light: the ground is re-rendered without it", {}},
      {"dampen",
       "lesson 04's blended shadow: the highlight and the light's colour show through",
       {{"block", 0}}},
      {"multi",
       "three surfaces, three coloured lights: each light's shadow in its own colour",
       {{"multi", 1}}},
      {"multi-one-light",
       "the general algorithm with one light, to read one shadow per surface",
       {{"multi", 1}, {"lights", 1}}},
  };
  info.shadows = true;
  info.passes = {"scene", "shadow", "unlit", "ambient", "light 1", "light 2", "light 3"};
  info.camera.distance = 8.0f;
  info.camera.azimuthDeg = 40.0f;
  info.camera.elevationDeg = 28.0f;
  info.camera.target = {-0.4f, 0.9f, -0.4f};
  return info;
}

}  // namespace

int main(int argc, char** argv) {
  return runLesson(
      lessonInfo(), [] { return std::make_unique<LightBlocking>(); }, argc, argv);
}
