// Lesson 00: stencil basics (Kilgard, "Improving Shadows and Reflections via the Stencil
// Buffer", section 1).
//
// The stencil buffer holds one small integer per pixel. Each fragment is tested against it
//     (ref & mask) FUNC (stencil & mask)
// and, depending on the outcome, one of three operations updates it:
//     sfail  - the stencil test failed,
//     dpfail - the stencil test passed but the depth test failed,
//     dppass - both passed.
// Writes go through the write mask, and so does glClear of the stencil buffer.
//
// Three demonstrations, one per group of variants:
//   keyhole      tag pixels in one pass (a keyhole shape, stencil only), then let the tag
//                decide which of two renderings of the scene each pixel shows.
//   ops          the three operations side by side: one draw lands three different values.
//   clear        glClear honours glStencilMask: a masked clear leaves the other bits alone.

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/mesh.h"
#include "geometry/shapes.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/shader.h"
#include "gl/stencil_view.h"

using namespace stencil;

namespace {

enum Demo { Keyhole = 0, Ops = 1, Clear = 2 };

// The stencil shapes, made after the lesson.
Mesh disc(float radius, int segments);
Mesh keyhole();

class StencilBasics final : public Lesson {
 public:
  StencilBasics()
      : lit_("common/lit.vert", "common/lit.frag"),
        flat_("common/flat.vert", "common/flat.frag"),
        ground_(makePlane(3.0f, 1)),
        torus_(makeTorus(0.8f, 0.3f, 48, 24)),
        cube_(makeCube(0.45f)),
        keyhole_(keyhole()),
        disc_(disc(0.38f, 64)),
        screen_(makeScreenQuad()) {}

  void render(Frame& f) override {
    switch (f.option("demo")) {
      case Keyhole: keyholeDemo(f); break;
      case Ops: opsDemo(f); break;
      case Clear: clearDemo(f); break;
    }
  }

 private:
  // ---- keyhole: tag, then test --------------------------------------------------------
  void keyholeDemo(Frame& f) {
    glClearColor(0.05f, 0.06f, 0.1f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    f.pass("clear");

    // Tag: write 1 wherever the keyhole covers, and nothing else anywhere.
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);                    // every fragment passes...
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);            // ...and stores the reference, 1
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // the tag is invisible
    glDepthMask(GL_FALSE);                                // and leaves depth alone
    const float slide = 0.45f * static_cast<float>(std::sin(0.8 * f.time));
    drawScreenShape(f, keyhole_, {slide, 0.1f}, 1.6f, {1, 1, 1, 1});
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    f.pass("tag");

    if (!f.on("stencil")) glDisable(GL_STENCIL_TEST);  // the artifact: nothing limits the passes
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);                  // the night pass redraws the same surfaces
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);  // from here on the stencil is only read
    glStencilFunc(GL_EQUAL, 1, 0xFF);        // day only inside the keyhole
    drawScene(f, false);
    f.pass("day");

    glStencilFunc(GL_NOTEQUAL, 1, 0xFF);  // night everywhere else
    drawScene(f, true);
    f.pass("night");
  }

  // ---- ops: stencil fail, depth fail, depth pass ----------------------------------------
  void opsDemo(Frame& f) {
    glClearColor(0.05f, 0.06f, 0.1f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    f.pass("clear");

    // Tag a disc with 1, as in the keyhole demo.
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    const float slide = 0.25f * static_cast<float>(std::sin(0.7 * f.time));
    drawScreenShape(f, disc_, {slide, 0.0f}, 1.0f, {1, 1, 1, 1});
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    f.pass("tag");

    // An occluder in front of part of the wall, drawn normally: it fills the depth buffer.
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    drawLit(f, cube_, glm::translate(glm::mat4(1), {0.6f, 0.6f, 0.8f}), {0.85f, 0.85f, 0.8f});
    f.pass("occluder");

    // One draw of a wall behind the occluder. The test reads bit 0 only: (0x81 & 1) == (s & 1)
    // passes inside the disc. Each outcome writes a different value:
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 0x81, 0x01);
    glStencilOp(GL_REPLACE,  // sfail: outside the disc (0) -> the reference, 0x81 = 129
                GL_INCR,     // dpfail: in the disc, behind the occluder (1) -> 2
                GL_INVERT);  // dppass: in the disc, visible (1) -> ~1 = 254
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // the wall itself stays invisible
    drawLit(f, screen_, glm::scale(glm::translate(glm::mat4(1), {0.0f, 0.6f, 0.0f}), {1.6f, 1.0f, 1.0f}),
            {1, 1, 1});
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    f.pass("ops");

    // The next pass reads the tags: one full-screen colour per outcome, blended over.
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    // Each outcome in the colour the stencil picture gives its value (--stencil-out, Tab).
    for (const GLint value : {0x81, 2, 0xFE}) {  // sfail, dpfail, dppass
      glStencilFunc(GL_EQUAL, value, 0xFF);      // only the pixels holding this outcome
      const auto c = stencilColour(static_cast<std::uint8_t>(value));
      drawFullScreen({c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, 0.8f});
    }
    glDisable(GL_BLEND);
    f.pass("show");
  }

  // ---- clear: the write mask applies to glClear -----------------------------------------
  void clearDemo(Frame& f) {
    glClearColor(0.05f, 0.06f, 0.1f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    f.pass("clear");

    // Two overlapping discs, each setting its own bit: left bit 0, right bit 1, overlap 3.
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0xFF, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    const float sway = 0.1f * static_cast<float>(std::sin(0.6 * f.time));
    glStencilMask(0x01);  // REPLACE writes the reference through the write mask: bit 0 only
    drawScreenShape(f, disc_, {-0.22f + sway, 0.0f}, 1.2f, {1, 1, 1, 1});
    glStencilMask(0x02);  // bit 1 only
    drawScreenShape(f, disc_, {0.22f + sway, 0.0f}, 1.2f, {1, 1, 1, 1});
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    f.pass("tag");

    // Clear the stencil again. glClear writes through glStencilMask like any other write.
    glStencilMask(f.on("masked-clear") ? 0x02 : 0xFF);
    glClear(GL_STENCIL_BUFFER_BIT);
    glStencilMask(0xFF);
    f.pass("clear-stencil");

    // Read bit 0: day where it survived, night elsewhere.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilFunc(GL_EQUAL, 1, 0x01);
    drawScene(f, false);
    f.pass("day");
    glStencilFunc(GL_NOTEQUAL, 1, 0x01);
    drawScene(f, true);
    f.pass("night");
  }

  // ---- drawing helpers (no stencil state in here) -----------------------------------------
  void drawScene(const Frame& f, bool night) {
    // The sky first, behind everything: bright by day, the clear colour by night, so the keyhole
    // shows day in its sky too. It neither tests nor writes depth: the scene covers it.
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    drawFullScreen(night ? glm::vec4(0.05f, 0.06f, 0.1f, 1.0f) : glm::vec4(0.55f, 0.72f, 0.92f, 1.0f));
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    const float t = static_cast<float>(f.time);
    glm::mat4 torus = glm::translate(glm::mat4(1), {-0.3f, 0.9f, 0.0f});
    torus = glm::rotate(torus, 0.7f * t, {0, 1, 0});
    torus = glm::rotate(torus, 1.1f, {1, 0, 0});
    drawLit(f, ground_, glm::mat4(1), {0.55f, 0.6f, 0.5f}, night);
    drawLit(f, torus_, torus, {0.9f, 0.45f, 0.2f}, night);
    drawLit(f, cube_, glm::translate(glm::mat4(1), {1.2f, 0.45f, 0.6f}), {0.3f, 0.5f, 0.9f}, night);
  }

  void drawLit(const Frame& f, const GpuMesh& mesh, const glm::mat4& model, glm::vec3 colour,
               bool night = false) {
    // Night: the same scene, dimmer and shifted to blue, so the two renderings read apart.
    lit_.set("model", model);
    lit_.set("viewProjection", f.projection * f.view);
    lit_.set("colour", night ? 0.5f * glm::mix(colour, glm::vec3(0.3f, 0.4f, 0.9f), 0.6f) : colour);
    lit_.set("toLight", glm::normalize(glm::vec3(0.4f, 0.8f, 0.5f)));
    lit_.set("ambient", 0.3f);
    mesh.draw();
  }

  // A 2D shape in normalised device coordinates, corrected for the aspect ratio.
  void drawScreenShape(const Frame& f, const GpuMesh& shape, glm::vec2 offset, float scale,
                       glm::vec4 colour) {
    const float aspect = static_cast<float>(f.size.x) / static_cast<float>(f.size.y);
    glm::mat4 m = glm::translate(glm::mat4(1), {offset, 0.0f});
    m = glm::scale(m, {scale / aspect, scale, 1.0f});
    flat_.set("transform", m);
    flat_.set("colour", colour);
    shape.draw();
  }

  void drawFullScreen(glm::vec4 colour) {
    flat_.set("transform", glm::mat4(1));
    flat_.set("colour", colour);
    screen_.draw();
  }

  Program lit_, flat_;
  GpuMesh ground_, torus_, cube_, keyhole_, disc_, screen_;
};

// ---- the stencil shapes ----------------------------------------------------------------------------

// A filled shape in the z=0 plane from a closed 2D outline, as a triangle fan around its
// centre (the outlines here are star-shaped about it).
Mesh fan(const std::vector<glm::vec2>& outline, glm::vec2 centre) {
  Mesh m;
  m.positions.push_back({centre, 0.0f});
  for (glm::vec2 p : outline) m.positions.push_back({p, 0.0f});
  const auto n = static_cast<std::uint32_t>(outline.size());
  for (std::uint32_t i = 0; i < n; ++i) m.indices.insert(m.indices.end(), {0u, 1 + i, 1 + (i + 1) % n});
  return m;
}

Mesh disc(float radius, int segments) {
  std::vector<glm::vec2> outline;
  for (int i = 0; i < segments; ++i) {
    const float a = 2.0f * glm::pi<float>() * static_cast<float>(i) / static_cast<float>(segments);
    outline.push_back(radius * glm::vec2(std::cos(a), std::sin(a)));
  }
  return fan(outline, {0, 0});
}

// A keyhole: a circle on top of a flared slot, about 0.9 units tall, centred on the origin.
Mesh keyhole() {
  std::vector<glm::vec2> outline;
  const float r = 0.25f, cy = 0.2f;
  const float a0 = std::asin(0.12f / r);  // where the slot meets the circle
  for (int i = 0; i <= 40; ++i) {
    const float a =
        -glm::half_pi<float>() + a0 + (2.0f * glm::pi<float>() - 2.0f * a0) * static_cast<float>(i) / 40.0f;
    outline.push_back({r * std::cos(a), cy + r * std::sin(a)});
  }
  outline.push_back({-0.2f, -0.5f});
  outline.push_back({0.2f, -0.5f});
  return fan(outline, {0.0f, 0.0f});
}

// ---- the lesson: options, variants, camera -------------------------------------------------------

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "00-stencil-basics";
  info.title = "Stencil basics";
  info.summary =
      "Tag pixels in one pass, control the next with the tag; the stencil function, reference,\n"
      "masks and the three operations; the write mask applies to glClear too.";
  info.options = {
      {"demo", 'D', "0 keyhole, 1 the three operations, 2 masked clear", Keyhole, 2},
      {"stencil", 'T', "the stencil test on; off shows what the tag was for", 1},
      {"masked-clear", 'M', "clear the stencil with write mask 0x02 instead of 0xFF", 1},
  };
  info.variants = {
      {"keyhole",
       "a keyhole tagged in the stencil shows the day scene, elsewhere night",
       {{"demo", Keyhole}}},
      {"stencil-off",
       "the same passes without the stencil test: night paints over everything",
       {{"demo", Keyhole}, {"stencil", 0}}},
      {"ops", "one draw, three outcomes: stencil fail, depth fail, depth pass", {{"demo", Ops}}},
      {"masked-clear",
       "glClear with write mask 0x02 clears bit 1 and keeps bit 0",
       {{"demo", Clear}, {"masked-clear", 1}}},
      {"full-clear", "glClear with write mask 0xFF clears both tags", {{"demo", Clear}, {"masked-clear", 0}}},
  };
  info.passes = {"clear", "tag", "day", "night", "occluder", "ops", "show", "clear-stencil"};
  info.camera.distance = 7.0f;
  info.camera.target = {0.0f, 0.6f, 0.0f};
  return info;
}

}  // namespace

int main(int argc, char** argv) {
  return runLesson(
      lessonInfo(), [] { return std::make_unique<StencilBasics>(); }, argc, argv);
}
