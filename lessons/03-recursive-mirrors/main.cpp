// Lesson 03: recursive mirrors (Kilgard, "Improving Shadows and Reflections via the Stencil
// Buffer", section 3, after Diefenbach; the stencil holds the recursion level).
//
// Lesson 02 reflected the scene once per mirror. Mirrors that see each other show
// reflections of reflections: inside a mirror's reflection the other mirrors must be
// reflected again, and so on. Depth first, with the stencil value as the level:
//   level k's scene is drawn where the stencil is k;
//   each mirror visible at level k: INCR its visible pixels to k + 1 (the tag), push their
//   depth to the far plane, draw level k + 1 there (the scene reflected once more, clipped
//   at that mirror), then restore the mirror's depth and DECR back to k.
// Every reflection multiplies the transform by one more reflection matrix, so the cull face
// flips with the sign of its determinant, and the images move away from the eye: the far
// plane must reach the deepest one. The number of scene renderings grows as
// 1 + n * sum_{i=1..r} (n-1)^(i-1) for n mirrors r bounces deep; a frustum through each
// mirror culls the objects and mirrors a reflection cannot show.

#include <algorithm>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <optional>
#include <string>

#include "geometry/bounds.h"
#include "geometry/mirror.h"
#include "geometry/planar.h"
#include "geometry/shapes.h"
#include "gl/errors.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/shader.h"

using namespace stencil;

namespace {

constexpr int kStencilBits = 8;
constexpr int kMaxLevel = (1 << kStencilBits) - 1;  // the deepest level the stencil can count
constexpr std::uint64_t kMaxRenderings = 20000;     // more would take minutes per frame

constexpr glm::vec4 kSky{0.55f, 0.65f, 0.8f, 1.0f};
constexpr float kInradius = 2.0f;  // from the room's centre to each mirror

// One re-rendering of the scene: level 0 is the real one; level k + 1 is seen in `mirror`
// from level k. Positions are drawn through `reflect`; `eye` is the eye carried back into
// the unreflected world (reflect^-1 applied to it), and `frustum` what the level can show
// there, so culling works on the scene as it is, never on reflected copies.
struct Level {
  int depth = 0;
  int mirror = -1;
  glm::mat4 reflect{1.0f};
  glm::vec3 eye{0.0f};
  Frustum frustum;
  glm::vec4 clip{0.0f};  // drawn-space plane: keep what lies behind the mirror as drawn
};

class RecursiveMirrors final : public Lesson {
 public:
  RecursiveMirrors()
      : light_("common/light.vert", "common/light.frag"),
        clipped_("common/light_clipped.vert", "common/light.frag"),
        flat_("common/flat.vert", "common/flat.frag"),
        glass_(makePlane(1.0f, 1)),
        box_(makeCube(1.0f)),
        torus_(makeTorus(0.4f, 0.14f, 40, 20)),
        sphere_(makeSphere(0.25f, 24, 12)),
        cone_(makeCone(0.25f, 0.6f, 24)),
        marker_(makeSphere(0.2f, 12, 6)) {}

  void render(Frame& f) override {
    const int depth = f.option("depth");
    if (depth > kMaxLevel)
      throw UsageError("recursion depth " + std::to_string(depth) + " needs stencil levels up to " +
                       std::to_string(depth) + "; " + std::to_string(kStencilBits) +
                       " stencil bits count only 0.." + std::to_string(kMaxLevel));
    setUpScene(f);

    // Plan first: which re-renderings the culling keeps, and how far the deepest one lies.
    Level root;
    root.eye = f.eye;
    root.frustum = viewFrustum(f.projection * f.view, false);  // the far plane is chosen below
    std::uint64_t planned = 0;
    float farthest = 0.0f;
    visit(f, root, [&](const Level& l) {
      if (++planned > kMaxRenderings)
        throw UsageError(std::to_string(f.option("mirrors")) + " mirrors " + std::to_string(depth) +
                         " bounces deep need more than " + std::to_string(kMaxRenderings) +
                         " scene renderings; lower the depth or turn culling on");
      farthest = std::max(farthest, glm::length(l.eye - sceneBounds_.centre) + sceneBounds_.radius);
    });
    const float cameraFar = f.projection[3][2] / (f.projection[2][2] + 1.0f);  // glm::perspective's far
    const glm::mat4 projection =
        f.on("far") && farthest > cameraFar ? withFarPlane(f.projection, farthest) : f.projection;
    viewProjection_ = projection * f.view;

    glClearColor(kSky.r, kSky.g, kSky.b, kSky.a);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);  // nearer surfaces hide farther ones
    glEnable(GL_CULL_FACE);   // closed objects, one-sided floor and glass
    if (f.on("birds-eye")) {
      renderBirdsEye(f, root);
      return;
    }

    glEnable(GL_STENCIL_TEST);  // the stencil holds the recursion level from here on
    renderLevel(f, root);
    f.pass("restore");  // every level restored: the stencil is 0 again everywhere

    // A record of where reflections show, for the stencil view and the measurements: each
    // top-level mirror's visible pixels get its number.
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // the picture is finished
    glDepthMask(GL_FALSE);                                // and changes no depth
    glDepthFunc(GL_LEQUAL);                               // the glass's depth was restored exactly
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);            // its visible pixels get its number
    glFrontFace(GL_CCW);                                  // the real mirrors, unreflected
    for (std::size_t i = 0; i < mirrors_.size(); ++i) {
      glStencilFunc(GL_ALWAYS, static_cast<GLint>(i + 1), 0xFF);  // mirror i's number
      drawGlass(light_, root, mirrors_[i]);
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    f.pass("mark");
  }

 private:
  // ---- the mirrors and the objects --------------------------------------------------------------

  struct Mirror {
    glm::vec3 centre, normal;  // the glass faces `normal`
    float halfWidth, halfHeight;

    glm::vec3 right() const { return glm::normalize(glm::cross(glm::vec3(0, 1, 0), normal)); }
    glm::vec3 up() const { return glm::cross(normal, right()); }
    glm::vec4 plane() const { return planeFrom(centre, normal); }
    std::vector<glm::vec3> corners() const {
      const glm::vec3 r = right() * halfWidth, u = up() * halfHeight;
      return {centre - r - u, centre + r - u, centre + r + u, centre - r + u};
    }
    glm::mat4 glassModel() const {  // makePlane's square (y = 0, facing +y), winding kept
      return {glm::vec4(right() * halfWidth, 0), glm::vec4(normal, 0), glm::vec4(-up() * halfHeight, 0),
              glm::vec4(centre, 1)};
    }
    glm::mat4 frameModel() const {  // a thin box just behind the glass: frame and back
      const float border = 0.07f, depth = 0.03f;
      return {glm::vec4(right() * (halfWidth + border), 0), glm::vec4(up() * (halfHeight + border), 0),
              glm::vec4(normal * depth, 0), glm::vec4(centre - normal * (depth + 0.005f), 1)};
    }
  };

  struct Object {
    const GpuMesh* mesh;
    glm::mat4 model;
    glm::vec3 colour;
    float shininess;
    BoundingSphere bounds;  // world space
  };

  // ---- the recursion ---------------------------------------------------------------------------

  // The levels seen from level l, one per mirror that can show something.
  std::vector<Level> childrenOf(const Frame& f, const Level& l) const {
    std::vector<Level> children;
    if (l.depth == f.option("depth")) return children;
    for (std::size_t i = 0; i < mirrors_.size(); ++i) {
      const Mirror& m = mirrors_[i];
      if (static_cast<int>(i) == l.mirror) continue;  // a plane mirror never sees itself
      if (f.on("culling") && (!facesEye(m.plane(), l.eye) || outside(l.frustum, m.corners())))
        continue;  // seen from behind, or outside what this level shows
      Level c;
      c.depth = l.depth + 1;
      c.mirror = static_cast<int>(i);
      const glm::mat4 r = reflectionMatrix(m.plane());
      c.reflect = l.reflect * r;  // the mirror is drawn through l.reflect, its images through one more
      c.eye = glm::vec3(r * glm::vec4(l.eye, 1.0f));
      if (f.on("culling")) c.frustum = throughMirror(l.frustum, l.eye, m.corners(), m.plane());
      c.clip = -transformPlane(m.plane(), l.reflect);  // behind the mirror as drawn at level l
      children.push_back(c);
    }
    return children;
  }

  void visit(const Frame& f, const Level& l, const std::function<void(const Level&)>& each) const {
    each(l);
    for (const Level& c : childrenOf(f, l)) visit(f, c, each);
  }

  // Level l's scene where the stencil holds l.depth, then each mirror's deeper levels.
  void renderLevel(Frame& f, const Level& l) {
    const GLint level = l.depth;
    glStencilFunc(GL_EQUAL, level, 0xFF);    // only this level's window
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);  // drawing the scene changes no level
    drawScene(f, l);
    f.count("scene_renderings");
    f.pass(l.depth == 0 ? "scene" : "reflection", l.depth == 0 ? "" : "level " + std::to_string(l.depth));
    for (const Level& c : childrenOf(f, l)) {
      const Mirror& m = mirrors_[static_cast<std::size_t>(c.mirror)];
      const Program& p = programFor(l);
      // Tag: the mirror's visible pixels at this level go one level deeper.
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // tagging draws no colour
      glDepthMask(GL_FALSE);                                // and keeps the glass's depth
      glDepthFunc(GL_LEQUAL);                  // the glass drawn with this level's scene: equal passes
      glStencilFunc(GL_EQUAL, level, 0xFF);    // inside this level's window...
      glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);  // ...the visible glass becomes level + 1
      useLevel(f, l);
      drawGlass(p, l, m);
      glDisable(GL_CLIP_DISTANCE0);

      // Far: the tagged depth to the far plane, the colour to the sky.
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);  // the sky, where the next level shows nothing
      glDepthMask(GL_TRUE);                             // the far depth is written
      glDepthFunc(GL_ALWAYS);                           // overwrite the glass's depth...
      glDepthRange(1.0, 1.0);                           // ...with the far plane's
      glStencilFunc(GL_EQUAL, level + 1, 0xFF);         // only the tag, which stays
      glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
      flat_.set("transform", viewProjection_ * l.reflect * m.glassModel());
      flat_.set("colour", kSky);
      glass_.draw();
      glDepthRange(0.0, 1.0);
      glDepthFunc(GL_LESS);

      renderLevel(f, c);  // the next level, and its own mirrors, depth first

      // Restore: the glass's depth back, the tag back to this level.
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // the reflection is the mirror's colour
      glDepthMask(GL_TRUE);                                 // the glass's depth is written...
      glDepthFunc(GL_ALWAYS);                               // ...over whatever the deeper levels left
      glStencilFunc(GL_EQUAL, level + 1, 0xFF);             // only the tag...
      glStencilOp(GL_KEEP, GL_KEEP, GL_DECR);               // ...which returns to this level
      useLevel(f, l);
      drawGlass(p, l, m);
      glDisable(GL_CLIP_DISTANCE0);
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      glDepthFunc(GL_LESS);
    }
  }

  // Figure 5 of the paper: every re-rendering the recursion would draw, without the stencil
  // and without clipping, from high above; a marker at each image of the eye.
  void renderBirdsEye(Frame& f, const Level& root) {
    const float aspect = static_cast<float>(f.size.x) / static_cast<float>(f.size.y);
    viewProjection_ =
        glm::perspective(glm::radians(45.0f), aspect, 1.0f, 200.0f) *
        glm::lookAt(glm::vec3(0.0f, 17.0f, 7.0f), glm::vec3(0.0f, 0.0f, -3.5f), glm::vec3(0, 1, 0));
    visit(f, root, [&](const Level& l) {
      useLevel(f, l);
      drawScene(f, l, /*floor=*/l.depth == 0, /*birdsEye=*/true);
      f.count("scene_renderings");
      flat_.set("transform",
                viewProjection_ * l.reflect * glm::translate(glm::mat4(1), f.eye));  // the eye's image
      flat_.set("colour",
                l.depth == 0 ? glm::vec4(1.0f, 0.95f, 0.3f, 1.0f) : glm::vec4(0.9f, 0.9f, 0.9f, 1.0f));
      marker_.draw();
    });
    glFrontFace(GL_CCW);
    glDisable(GL_CULL_FACE);
    f.pass("scene");
  }

  // ---- drawing -----------------------------------------------------------------------------------

  const Program& programFor(const Level& l) const { return l.depth > 0 ? clipped_ : light_; }

  // The state a level's draws need: the winding its reflections leave, and its clip plane.
  void useLevel(const Frame& f, const Level& l) const {
    const bool mirrored = glm::determinant(l.reflect) < 0.0f;
    // An odd number of reflections turns every winding over: front faces become clockwise.
    glFrontFace(mirrored && f.on("flip") ? GL_CW : GL_CCW);
    if (l.depth > 0 && !f.on("birds-eye"))
      glEnable(GL_CLIP_DISTANCE0);  // only with the shader that writes it
  }

  void drawScene(const Frame& f, const Level& l, bool floor = true, bool birdsEye = false) const {
    const Program& p = birdsEye ? light_ : programFor(l);
    useLevel(f, l);
    p.set("viewProjection", viewProjection_);
    p.set("light", l.reflect * kLight);  // lit as in the real world, then mirrored with it
    p.set("lightColour", glm::vec3(1.1f, 1.05f, 1.0f));
    p.set("ambient", glm::vec3(0.3f));
    p.set("eye", f.eye);
    p.set("clipPlane", l.clip);
    const bool cull = f.on("culling");
    for (const Object& o : objects_) {
      if (!floor && o.mesh == &*floor_) continue;
      if (cull && outside(l.frustum, o.bounds)) continue;  // no reflection at this level shows it
      p.set("model", l.reflect * o.model);
      p.set("colour", o.colour);
      p.set("shininess", o.shininess);
      o.mesh->draw();
    }
    for (std::size_t i = 0; i < mirrors_.size(); ++i) {
      if (static_cast<int>(i) == l.mirror) continue;  // behind its own glass: clipped anyway
      if (cull && outside(l.frustum, mirrors_[i].corners())) continue;
      p.set("model", l.reflect * mirrors_[i].frameModel());
      p.set("colour", glm::vec3(0.35f, 0.25f, 0.2f));
      p.set("shininess", 16.0f);
      box_.draw();
      drawGlass(p, l, mirrors_[i]);  // plain glass: what the deepest level shows
    }
    glDisable(GL_CLIP_DISTANCE0);
  }

  void drawGlass(const Program& p, const Level& l, const Mirror& m) const {
    p.set("viewProjection", viewProjection_);
    p.set("clipPlane", l.clip);
    p.set("model", l.reflect * m.glassModel());
    p.set("colour", glm::vec3(0.16f, 0.2f, 0.24f));
    p.set("shininess", 96.0f);
    glass_.draw();
  }

  // ---- the scene -----------------------------------------------------------------------------

  // n mirrors on a regular polygon around the origin, facing in; mirror 0 at z = -2 faces +z.
  // Two face each other across the room; one is mirror 0 alone.
  void setUpScene(const Frame& f) {
    const int n = f.option("mirrors");
    const float pi = glm::pi<float>();
    const float halfWidth = n <= 2 ? 1.6f : kInradius * std::tan(pi / static_cast<float>(n)) - 0.15f;
    mirrors_.clear();
    for (int i = 0; i < n; ++i) {
      const float a = 2.0f * pi * static_cast<float>(i) / static_cast<float>(n);
      const glm::vec3 normal(std::sin(a), 0.0f, std::cos(a));
      mirrors_.push_back({glm::vec3(0.0f, 1.05f, 0.0f) - kInradius * normal, normal, halfWidth, 0.9f});
    }
    const float floorHalf = n <= 2 ? kInradius : kInradius / std::cos(pi / static_cast<float>(n));
    if (!floor_ || floorHalf != floorHalf_) {
      floor_.emplace(makePlane(floorHalf, 1));
      floorHalf_ = floorHalf;
    }
    const float t = static_cast<float>(f.time);
    glm::mat4 torus = glm::translate(glm::mat4(1), {-0.1f, 0.85f, -0.9f});
    torus = glm::rotate(glm::rotate(torus, 0.6f * t, {0, 1, 0}), 1.1f + 0.4f * t, {1, 0, 0.3f});
    objects_ = {
        {&*floor_, glm::mat4(1), {0.72f, 0.7f, 0.62f}, 16.0f, {{0, 0, 0}, floorHalf * 1.4143f}},
        {&torus_, torus, {0.9f, 0.45f, 0.2f}, 48.0f, {glm::vec3(torus[3]), 0.541f}},
        {&sphere_,
         glm::translate(glm::mat4(1), {0.8f, 0.25f, -1.2f}),
         {0.25f, 0.45f, 0.9f},
         64.0f,
         {{0.8f, 0.25f, -1.2f}, 0.251f}},
        {&cone_,
         glm::translate(glm::mat4(1), {-0.9f, 0.3f, -1.0f}),
         {0.85f, 0.2f, 0.25f},
         32.0f,
         {{-0.9f, 0.3f, -1.0f}, 0.391f}},
    };
    // Everything any level draws: the floor and the mirrors around it.
    sceneBounds_ = {{0.0f, 1.0f, 0.0f}, floorHalf * 1.4143f + 1.0f};
  }

  static constexpr glm::vec4 kLight{0.8f, 3.5f, 0.8f, 1.0f};

  Program light_, clipped_, flat_;
  GpuMesh glass_, box_, torus_, sphere_, cone_, marker_;
  std::optional<GpuMesh> floor_;
  float floorHalf_ = 0.0f;
  std::vector<Mirror> mirrors_;
  std::vector<Object> objects_;
  BoundingSphere sceneBounds_;
  glm::mat4 viewProjection_{1.0f};
};

// ---- the lesson: options, variants, camera -------------------------------------------------------

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "03-recursive-mirrors";
  info.title = "Recursive mirrors";
  info.summary =
      "Reflections of reflections: the stencil counts the recursion level with INCR and DECR, depth\n"
      "first; a hall of mirrors, mirrors that all see each other, culling and the far plane.";
  info.stencilBits = kStencilBits;
  info.options = {
      {"mirrors", 'N',
       "mirrors on a regular polygon facing inwards (2: two parallel mirrors; 1: one; 0: none)", 2, 6},
      {"depth", 'D', "how many bounces deep (the stencil counts up to 255)", 8, 1000},
      {"culling", 'C', "cull objects and mirrors outside a frustum through each mirror", 1},
      {"far", 'F', "move the far plane out to the deepest reflection drawn", 1},
      {"flip", 'L', "flip the cull face with each reflection's determinant", 1},
      {"birds-eye", 'B', "every re-rendering drawn without the stencil, seen from above", 0},
  };
  info.variants = {
      {"hall", "two parallel mirrors, 8 bounces: the hall of mirrors", {}},
      {"hall-shallow", "the same hall, 2 bounces: deeper mirrors show plain glass", {{"depth", 2}}},
      {"three-mirrors", "three mirrors that see each other, 4 bounces", {{"mirrors", 3}, {"depth", 4}}},
      {"far-plane", "the hall with the camera's far plane: deep reflections cut off", {{"far", 0}}},
      {"birds-eye",
       "the re-renderings of three mirrors, 3 bounces, drawn without the stencil and seen from above",
       {{"mirrors", 3}, {"depth", 3}, {"birds-eye", 1}}},
  };
  info.passes = {"scene", "reflection", "restore", "mark"};  // "reflection": one per level drawn
  info.camera.target = {0.0f, 1.0f, -2.0f};                  // on the first mirror
  info.camera.distance = 3.7f;
  info.camera.azimuthDeg = 22.0f;
  info.camera.elevationDeg = 8.0f;
  info.camera.farPlane = 20.0f;  // the hall's fourth reflection lies beyond it
  return info;
}

}  // namespace

int main(int argc, char** argv) {
  return runLesson(
      lessonInfo(), [] { return std::make_unique<RecursiveMirrors>(); }, argc, argv);
}
