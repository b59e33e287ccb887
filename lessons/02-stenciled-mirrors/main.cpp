// Lesson 02: stenciled mirrors (Kilgard, "Improving Shadows and Reflections via the Stencil
// Buffer", section 3).
//
// Lesson 01 drew the reflected scene and hoped the real scene would cover whatever leaked.
// The stencil removes the hope. For each mirror, after the scene is drawn:
//   1 tag      the mirror's visible pixels get the tag 1 (depth tested against the scene);
//   2 far      inside the tag, the depth is reset to the far plane, so the reflection can be
//              drawn "behind" the mirror's surface, and the colour to the sky's;
//   3 reflect  the scene, mirrored through the mirror's plane, only where the tag is, clipped
//              at the mirror's plane so nothing behind the mirror can appear in it;
//   4 restore  inside the tag, the mirror's own depth is written back (the reflection must
//              not let later geometry show through the mirror), and the tag is cleared so the
//              next mirror's passes do not see it.
// A mirror in front of another simply re-tags the pixels it covers: its depth is nearer.

#include <array>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/mirror.h"
#include "geometry/planar.h"
#include "geometry/shapes.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/shader.h"

using namespace stencil;

namespace {

constexpr GLint kTag = 1;   // a mirror's visible pixels while it is being reflected
constexpr GLint kDone = 2;  // a reflection was drawn here: not the tag, so later mirrors skip it
static_assert(kDone == kTag + 1, "the restore pass turns the tag into kDone with GL_INCR");

// A rectangular one-sided mirror: its glass faces `normal`.
struct Mirror {
  glm::vec3 centre, normal;
  float halfWidth, halfHeight;

  glm::vec3 right() const { return glm::normalize(glm::cross(glm::vec3(0, 1, 0), normal)); }
  glm::vec3 up() const { return glm::cross(normal, right()); }
  glm::vec4 plane() const { return planeFrom(centre, normal); }
  // makePlane's square (y = 0, facing +y) turned into the glass, winding kept.
  glm::mat4 glassModel() const {
    return {glm::vec4(right() * halfWidth, 0), glm::vec4(normal, 0), glm::vec4(-up() * halfHeight, 0),
            glm::vec4(centre, 1)};
  }
  // A thin box just behind the glass, a little larger: the frame and the mirror's back.
  glm::mat4 frameModel() const {
    const float border = 0.07f, depth = 0.03f;
    return {glm::vec4(right() * (halfWidth + border), 0), glm::vec4(up() * (halfHeight + border), 0),
            glm::vec4(normal * depth, 0), glm::vec4(centre - normal * (depth + 0.005f), 1)};
  }
};

glm::vec3 facing(float degrees) {  // a horizontal direction, 0 degrees = +z
  return {std::sin(glm::radians(degrees)), 0.0f, std::cos(glm::radians(degrees))};
}

class StenciledMirrors final : public Lesson {
 public:
  StenciledMirrors()
      : light_("common/light.vert", "common/light.frag"),
        clipped_("common/light_clipped.vert", "common/light.frag"),
        marble_("common/light.vert", "02-stenciled-mirrors/marble.frag"),
        flat_("common/flat.vert", "common/flat.frag"),
        floor_(makePlane(4.0f, 1)),
        glass_(makePlane(1.0f, 1)),
        box_(makeCube(1.0f)),
        torus_(makeTorus(0.45f, 0.16f, 40, 20)),
        sphere_(makeSphere(0.4f, 32, 16)),
        cone_(makeCone(0.35f, 0.8f, 32)),
        rod_(makeCylinder(0.07f, 3.0f, 24)) {}

  void render(Frame& f) override {
    const std::vector<Mirror> mirrors = mirrorsAt(f);
    const glm::vec4 light = {1.5f, 4.5f, 2.5f, 1.0f};

    // ---- the scene, mirrors as plain glass ---------------------------------------------------
    glClearColor(kSky.r, kSky.g, kSky.b, kSky.a);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);  // nearer surfaces hide farther ones, in the scene and in each reflection
    glEnable(GL_CULL_FACE);   // closed objects, one-sided floor and glass: back faces never show
    drawScene(f, mirrors, glm::mat4(1), light, nullptr, -1);
    f.count("scene_renderings");
    f.pass("scene");

    for (std::size_t k = 0; k < mirrors.size(); ++k) {
      const std::size_t i = f.on("order") ? mirrors.size() - 1 - k : k;
      const Mirror& m = mirrors[i];
      const bool stencil = f.on("stencil");
      // ---- 1 tag the mirror's visible pixels ----------------------------------------------
      if (stencil) {
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_ALWAYS, kTag, 0xFF);       // wherever the glass is visible...
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);  // ...it is tagged, even over an earlier mirror
      }
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // tagging draws no colour
      glDepthMask(GL_FALSE);                                // and keeps the glass's depth
      glDepthFunc(GL_LEQUAL);  // the glass is in the depth buffer already: equal passes, nearer objects win
      drawGlass(f, m, glm::mat4(1), light, light_);
      f.pass("tag");

      // ---- 2 push the tagged depth to the far plane ----------------------------------------
      if (stencil) {
        glStencilFunc(GL_EQUAL, kTag, 0xFF);     // only the tag...
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);  // ...which stays
      }
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);  // the sky, where the reflection shows nothing
      glDepthMask(GL_TRUE);                             // the far depth is written:
      glDepthFunc(GL_ALWAYS);                           // overwrite the glass's depth...
      glDepthRange(1.0, 1.0);                           // ...with the far plane's
      flat_.set("transform", f.projection * f.view * m.glassModel());
      flat_.set("colour", kSky);
      glass_.draw();
      glDepthRange(0.0, 1.0);
      glDepthFunc(GL_LESS);
      f.pass("far");

      // ---- 3 the reflected scene, only on the tag and only what stands in front ---------------
      if (f.on("reflect")) {
        const glm::mat4 reflect = reflectionMatrix(m.plane());
        glFrontFace(GL_CW);  // the reflection matrix's determinant is -1: it turns windings over
        // Keep what the mirror's glass hides: the drawn images behind its plane.
        const glm::vec4 behind = -m.plane();
        if (f.on("clip")) glEnable(GL_CLIP_DISTANCE0);  // only for the shader that writes it
        drawScene(f, mirrors, reflect, light, f.on("clip") ? &behind : nullptr, static_cast<int>(i));
        f.count("scene_renderings");
        glDisable(GL_CLIP_DISTANCE0);
        glFrontFace(GL_CCW);
      }
      f.pass("reflection");

      // ---- 4 restore the glass's depth, and clear the tag ------------------------------------
      if (stencil) {
        glStencilFunc(GL_EQUAL, kTag, 0xFF);     // only the tag,
        glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);  // which becomes 2: not the tag any more
      }
      glDepthMask(GL_TRUE);    // the glass's own depth is written back...
      glDepthFunc(GL_ALWAYS);  // ...over the reflection's
      if (f.on("semi")) {
        glEnable(GL_BLEND);  // the stone over its reflection
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        drawMarble(f, m, light);
        glDisable(GL_BLEND);
      } else {
        // A perfect mirror: the reflection is its colour.
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        drawGlass(f, m, glm::mat4(1), light, light_);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      }
      glDepthFunc(GL_LESS);
      glDisable(GL_STENCIL_TEST);
      f.pass("restore");
    }
    glDisable(GL_CULL_FACE);
  }

 private:
  std::vector<Mirror> mirrorsAt(const Frame& f) const {
    std::vector<Mirror> all = {
        {{0.0f, 1.1f, -2.2f}, facing(12.0f), 1.7f, 1.0f},      // the back mirror
        {{-1.0f, 0.85f, -0.7f}, facing(35.0f), 0.55f, 0.75f},  // in front of the back mirror's left half
        {{2.4f, 0.95f, -0.6f}, facing(-70.0f), 0.8f, 0.85f},   // to the right, facing the objects
    };
    if (f.on("grazing")) {
      // Turned until the eye sees the glass 6 degrees off edge-on.
      const glm::vec3 toEye = glm::normalize(glm::vec3(f.eye.x, 0.0f, f.eye.z) -
                                             glm::vec3(all[2].centre.x, 0.0f, all[2].centre.z));
      const glm::vec3 edgeOn = glm::cross(glm::vec3(0, 1, 0), toEye);
      const float a = glm::radians(6.0f);
      all[2].normal = glm::normalize(std::cos(a) * edgeOn + std::sin(a) * toEye);
    }
    all.resize(static_cast<std::size_t>(f.option("mirrors")));
    return all;
  }

  // The rod: through the first mirror, its near end out towards the viewer's left.
  static glm::mat4 rodModel(const Mirror& m) {
    const glm::mat4 place = glm::translate(glm::mat4(1), m.centre + 0.25f * m.right() - 0.2f * m.up());
    return glm::rotate(glm::rotate(place, glm::radians(-50.0f), glm::vec3(0, 1, 0)), glm::radians(80.0f),
                       glm::vec3(1, 0, 0));
  }

  void setLight(const Program& p, const Frame& f, const glm::mat4& reflect, glm::vec4 light) const {
    p.set("viewProjection", f.projection * f.view);
    p.set("light", reflect * light);  // lit as in the real world, then mirrored with the scene
    p.set("lightColour", glm::vec3(1.1f, 1.05f, 1.0f));
    p.set("ambient", glm::vec3(0.3f));
    p.set("eye", f.eye);
  }

  void drawLit(const Program& p, const GpuMesh& mesh, const glm::mat4& model, glm::vec3 colour,
               float shininess) const {
    p.set("model", model);
    p.set("colour", colour);
    p.set("shininess", shininess);
    mesh.draw();
  }

  // Everything but the mirrors' reflections, through `reflect` (the identity for the real
  // scene). A reflection is clipped to `clip` when given, and leaves out the mirror it is in.
  void drawScene(const Frame& f, const std::vector<Mirror>& mirrors, const glm::mat4& reflect,
                 glm::vec4 light, const glm::vec4* clip, int reflectedIn) const {
    const Program& p = clip ? clipped_ : light_;
    setLight(p, f, reflect, light);
    if (clip) p.set("clipPlane", *clip);
    const float t = static_cast<float>(f.time);
    drawLit(p, floor_, reflect, {0.72f, 0.7f, 0.62f}, 16.0f);
    glm::mat4 torus = glm::translate(glm::mat4(1), {0.2f, 0.75f, 0.4f});
    torus = glm::rotate(glm::rotate(torus, 0.6f * t, {0, 1, 0}), 1.1f + 0.4f * t, {1, 0, 0.3f});
    drawLit(p, torus_, reflect * torus, {0.9f, 0.45f, 0.2f}, 48.0f);
    drawLit(p, sphere_, reflect * glm::translate(glm::mat4(1), {1.2f, 0.4f, 1.3f}), {0.25f, 0.45f, 0.9f},
            64.0f);
    drawLit(p, box_,
            reflect * glm::rotate(glm::translate(glm::mat4(1), {-1.5f, 0.3f, 1.2f}), 0.3f * t, {0, 1, 0}) *
                glm::scale(glm::mat4(1), glm::vec3(0.3f)),
            {0.3f, 0.75f, 0.35f}, 32.0f);
    drawLit(p, cone_, reflect * glm::translate(glm::mat4(1), {0.9f, 0.4f, -1.1f}), {0.85f, 0.2f, 0.25f},
            32.0f);
    // Behind the back mirror, out of the camera's sight: only a reflection without a clip plane shows it.
    drawLit(p, box_,
            reflect * glm::translate(glm::mat4(1), {0.5f, 0.35f, -3.1f}) *
                glm::scale(glm::mat4(1), glm::vec3(0.35f)),
            {0.6f, 0.3f, 0.75f}, 32.0f);
    for (std::size_t j = 0; j < mirrors.size(); ++j) {
      if (static_cast<int>(j) == reflectedIn)
        continue;  // a mirror never shows itself (its frame is behind its glass)
      drawLit(p, box_, reflect * mirrors[j].frameModel(), {0.35f, 0.25f, 0.2f}, 16.0f);
      drawGlass(f, mirrors[j], reflect, light, p);
    }
    if (!f.on("straddle") || mirrors.empty()) return;
    const glm::mat4 rod = reflect * rodModel(mirrors[0]);
    if (f.on("cut") && !clip) {
      // The straddle test's reference: a rod that ends at the first mirror's plane.
      setLight(clipped_, f, reflect, light);
      clipped_.set("clipPlane", transformPlane(mirrors[0].plane(), reflect));
      glEnable(GL_CLIP_DISTANCE0);
      drawLit(clipped_, rod_, rod, kRodColour, 48.0f);
      glDisable(GL_CLIP_DISTANCE0);
    } else {
      drawLit(p, rod_, rod, kRodColour, 48.0f);
    }
  }

  // The glass without reflections: dark, with the light's highlight.
  void drawGlass(const Frame& f, const Mirror& m, const glm::mat4& reflect, glm::vec4 light,
                 const Program& p) const {
    setLight(p, f, reflect, light);
    drawLit(p, glass_, reflect * m.glassModel(), {0.16f, 0.2f, 0.24f}, 96.0f);
  }

  void drawMarble(const Frame& f, const Mirror& m, glm::vec4 light) const {
    setLight(marble_, f, glm::mat4(1), light);
    marble_.set("alpha", 0.55f);
    drawLit(marble_, glass_, m.glassModel(), {0.92f, 0.9f, 0.86f}, 80.0f);
  }

  static constexpr glm::vec3 kRodColour{0.95f, 0.85f, 0.2f};
  static constexpr glm::vec4 kSky{0.55f, 0.65f, 0.8f, 1.0f};
  Program light_, clipped_, marble_, flat_;
  GpuMesh floor_, glass_, box_, torus_, sphere_, cone_, rod_;
};

// ---- the lesson: options, variants, camera -------------------------------------------------------

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "02-stenciled-mirrors";
  info.title = "Stenciled mirrors";
  info.summary =
      "Kilgard's steps per mirror: tag the visible mirror pixels, reset their depth, draw the reflected\n"
      "scene only there with a clip plane at the mirror, restore the depth and clear the tag.";
  info.options = {
      {"stencil", 'T', "tag each mirror and draw its reflection only on the tag", 1},
      {"clip", 'C', "clip the reflected scene at the mirror's plane (gl_ClipDistance)", 1},
      {"reflect", 'E', "draw the reflections at all (off: plain glass, the tests' reference)", 1},
      {"semi", 'M', "semi-reflective: polished marble blended over the reflection", 0},
      {"mirrors", 'N', "how many of the three mirrors stand in the scene", 3, 3},
      {"straddle", 'D', "a rod straddling the first mirror's plane (a hard case)", 0},
      {"cut", 'X', "cut the rod at the mirror's plane (the straddle test's reference)", 0},
      {"grazing", 'G', "turn the third mirror almost edge-on to the eye (a hard case)", 0},
      {"order", 'O', "process the mirrors in reverse order (the picture must not change)", 0},
  };
  info.variants = {
      {"mirrors", "three stenciled mirrors, one in front of another", {}},
      {"semi-reflective", "polished marble: the reflection blended with the stone", {{"semi", 1}}},
      {"stencil-off",
       "the same steps without the tag or the clip plane: lesson 01's leaks come back",
       {{"stencil", 0}, {"clip", 0}}},
      {"no-clip", "stencil but no clip plane: what stands behind a mirror appears in it", {{"clip", 0}}},
      {"straddle",
       "a rod through the mirror: only its part on the reflective side is reflected",
       {{"mirrors", 1}, {"straddle", 1}}},
      {"grazing", "the third mirror seen almost edge-on: a thin reflection, no leak", {{"grazing", 1}}},
  };
  info.passes = {"scene", "tag", "far", "reflection", "restore"};
  info.camera.distance = 8.5f;
  info.camera.azimuthDeg = 25.0f;
  info.camera.elevationDeg = 22.0f;
  info.camera.target = {0.0f, 0.8f, -0.5f};
  return info;
}

}  // namespace

int main(int argc, char** argv) {
  return runLesson(
      lessonInfo(), [] { return std::make_unique<StenciledMirrors>(); }, argc, argv);
}
