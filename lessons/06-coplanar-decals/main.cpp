// Lesson 06: co-planar decals (Kilgard, "Improving Shadows and Reflections via the Stencil
// Buffer", section 7).
//
// A runway carries painted markings (threshold bars, centre-line dashes, edge lines) and,
// when the aircraft flies over, its shadow. All of it lies exactly in the runway's plane, so
// a marking and the runway have the same depth at every pixel, up to the rounding of two
// different triangles' interpolation: with the ordinary depth test that rounding decides,
// pixel by pixel, which one shows (z-fighting).
//
// The stencil recipe:
//   1. draw the runway with the depth test on, tagging the pixels where it is visible;
//   2. draw the decals with the depth test off, only on the tag: no depth comparison, so
//      nothing to fight over, and the tag keeps them off anything in front of the runway;
//   3. the decals never write depth, so the depth buffer still holds the runway's true
//      depths and everything drawn afterwards is depth-tested against the real surface.
// The shadow is the last decal; it clears the tag as it darkens, so it blends once (lesson 04).
//
// For comparison: the plain depth test (z-fighting), the usual fix glPolygonOffset (works,
// but needs tuning and a larger offset for every layer, and the depth it writes is no longer
// the surface's), and the depth test simply off without the stencil (decals paint over
// whatever stands in front of the runway).

#include <cmath>
#include <cstdint>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/mesh.h"
#include "geometry/planar.h"
#include "geometry/shapes.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/shader.h"

using namespace stencil;

namespace {

enum Method { Stencil = 0, DepthTest = 1, PolygonOffset = 2, DepthOff = 3 };

constexpr float kRunwayHalfWidth = 1.2f, kRunwayHalfLength = 7.0f;
constexpr float kShadowAlpha = 0.5f;  // the shadow keeps half the light, once
constexpr GLint kRunwayTag = 1;
constexpr glm::vec3 kTower{1.7f, 0.0f, 7.1f};  // beside the runway, between it and the camera
constexpr glm::vec3 kArch{0.0f, 0.0f, 3.9f};   // across the runway, its feet in the aiming blocks
constexpr glm::vec3 kPaint{0.92f, 0.92f, 0.86f};

glm::mat4 at(glm::vec3 position) {
  return glm::translate(glm::mat4(1), position);
}

// The scene's meshes, built after the lesson.
Mesh makeMarkings();
Mesh makeAircraft();

class CoplanarDecals final : public Lesson {
 public:
  CoplanarDecals()
      : lit_("common/lit.vert", "common/lit.frag"),
        flat_("common/flat.vert", "common/flat.frag"),
        grass_(makePlane(200.0f, 1)),
        runway_(transformed(makePlane(1.0f, 1),
                            glm::scale(glm::mat4(1), {kRunwayHalfWidth, 1.0f, kRunwayHalfLength}))),
        markings_(makeMarkings()),
        aircraft_(makeAircraft()),
        arch_(makeTorus(0.55f, 0.08f, 48, 12)),
        tower_(makeCylinder(0.12f, 1.7f, 20)),
        cab_(makeCube(0.2f)) {}

  void render(Frame& f) override {
    const auto method = static_cast<Method>(f.option("method"));
    const glm::vec4 sun = glm::vec4(glm::normalize(glm::vec3(0.3f, 1.0f, 0.45f)), 0.0f);  // w = 0
    const glm::vec4 runwayPlane = planeFrom({0, 0, 0}, {0, 1, 0});

    // ---- scenery: the grass below the runway and a tower in front of part of it -----------
    glClearColor(0.55f, 0.68f, 0.85f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);  // ordinary opaque geometry, GL_LESS
    glDisable(GL_CULL_FACE);  // the grass is one open plane
    // The grass lies a little below the runway, not in its plane: the two never tie.
    drawLit(f, grass_, at({0.0f, -0.05f, 0.0f}), {0.35f, 0.55f, 0.25f}, sun);
    glEnable(GL_CULL_FACE);  // the tower is closed: back faces are never seen
    drawLit(f, tower_, at(kTower + glm::vec3(0, 0.8f, 0)), {0.8f, 0.78f, 0.72f}, sun);
    drawLit(f, cab_, at(kTower + glm::vec3(0, 1.9f, 0)), {0.3f, 0.42f, 0.55f}, sun);
    f.pass("scenery");

    // ---- the runway: the base surface, tagged where it is visible --------------------------
    if (method == Stencil) {
      glEnable(GL_STENCIL_TEST);                   // the tag is the whole recipe
      glStencilFunc(GL_ALWAYS, kRunwayTag, 0xFF);  // drawn after the tower, so only where the
      glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);   // runway passes the depth test gets the tag
    }
    glDisable(GL_CULL_FACE);  // an open plane, like the grass
    drawLit(f, runway_, glm::mat4(1), {0.32f, 0.32f, 0.34f}, sun);
    f.pass("runway");

    // ---- the markings: co-planar with the runway ------------------------------------------
    if (f.on("decals")) {
      switch (method) {
        case Stencil:
          glDisable(GL_DEPTH_TEST);                   // nothing to fight over; and no depth writes
          glStencilFunc(GL_EQUAL, kRunwayTag, 0xFF);  // only on the visible runway...
          glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);     // ...which stays tagged for the shadow
          break;
        case DepthTest: break;  // GL_LESS against the same depths: rounding picks the winner
        case PolygonOffset:
          glEnable(GL_POLYGON_OFFSET_FILL);
          glPolygonOffset(-1.0f, -1.0f);  // pulled towards the eye; the pulled depth is written
          break;
        case DepthOff: glDisable(GL_DEPTH_TEST); break;  // no fight, but nothing hides them either
      }
      drawLit(f, markings_, glm::mat4(1), kPaint, sun);
    }
    f.pass("decals");

    // ---- the shadow: the aircraft flattened onto the runway, the last decal ---------------
    const glm::mat4 aircraft = aircraftModel(f);
    if (f.on("decals")) {
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      glEnable(GL_CULL_FACE);  // the faces towards the sun: one layer per layer of aircraft
      switch (method) {
        case Stencil:                                 // the depth test is still off
          glStencilFunc(GL_EQUAL, kRunwayTag, 0xFF);  // still only on the visible runway...
          glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);     // ...and once: darkening clears the tag
          break;
        case DepthTest:
          glDepthMask(GL_FALSE);  // translucent: it must not hide the runway from itself
          break;
        case PolygonOffset:
          glDepthMask(GL_FALSE);          // translucent, as above
          glPolygonOffset(-2.0f, -2.0f);  // a second layer needs more offset than the markings
          break;
        case DepthOff: break;  // the depth test is still off from the markings
      }
      flat_.set("transform", f.projection * f.view * planarShadowMatrix(runwayPlane, sun) * aircraft);
      flat_.set("colour", glm::vec4(0.0f, 0.0f, 0.0f, kShadowAlpha));
      aircraft_.draw();
      glDisable(GL_BLEND);
      glDisable(GL_POLYGON_OFFSET_FILL);  // back to plain opaque drawing
      glDepthMask(GL_TRUE);               // (depth writes for the objects)
    }
    f.pass("shadow");

    // ---- objects drawn afterwards are depth-tested against the runway's true depth --------
    glDisable(GL_STENCIL_TEST);  // done with the tags (the next frame's glClear resets them)
    glEnable(GL_DEPTH_TEST);     // the runway's depths are still in the buffer
    glEnable(GL_CULL_FACE);      // closed objects
    drawLit(f, aircraft_, aircraft, {0.95f, 0.72f, 0.2f}, sun);
    // The arch is a torus stood upright, half of it below the surface: the runway's depth hides that half.
    const glm::mat4 arch = glm::rotate(at(kArch), glm::radians(90.0f), {1, 0, 0});
    drawLit(f, arch_, arch, {0.8f, 0.22f, 0.15f}, sun);
    f.pass("objects");
  }

 private:
  // The aircraft flies down the runway (towards -z) at a constant height, round and round.
  static glm::mat4 aircraftModel(const Frame& f) {
    const float lap = 16.0f;  // from z = +8 to z = -8, then again
    const float z = 8.0f - std::fmod(2.0f * static_cast<float>(f.time) + 5.0f, lap);
    return glm::rotate(at({0.0f, 1.1f, z}), 0.15f, {0, 0, 1});  // a slight bank
  }

  void drawLit(const Frame& f, const GpuMesh& mesh, const glm::mat4& model, glm::vec3 colour, glm::vec4 sun) {
    lit_.set("model", model);
    lit_.set("viewProjection", f.projection * f.view);
    lit_.set("colour", colour);
    lit_.set("toLight", glm::vec3(sun));
    lit_.set("ambient", 0.4f);
    mesh.draw();
  }

  Program lit_, flat_;
  GpuMesh grass_, runway_, markings_, aircraft_, arch_, tower_, cab_;
};

// ---- the scene's meshes ---------------------------------------------------------------------------

// One more part in a mesh, placed by `placement` (normals follow through `transformed`).
void append(Mesh& into, const Mesh& part, const glm::mat4& placement) {
  const Mesh moved = transformed(part, placement);
  const auto base = static_cast<std::uint32_t>(into.positions.size());
  into.positions.insert(into.positions.end(), moved.positions.begin(), moved.positions.end());
  into.normals.insert(into.normals.end(), moved.normals.begin(), moved.normals.end());
  for (std::uint32_t i : moved.indices) into.indices.push_back(base + i);
}

// A w x l rectangle in the runway's plane (y = 0), centred at (x, z).
void addMark(Mesh& into, float x, float z, float w, float l) {
  append(into, makePlane(0.5f, 1), glm::scale(at({x, 0.0f, z}), {w, 1.0f, l}));
}

// The painted markings, all in y = 0 like the runway itself, as one mesh.
Mesh makeMarkings() {
  Mesh m;
  for (float end : {-1.0f, 1.0f}) {
    for (float i : {0.0f, 1.0f, 2.0f, 3.0f})  // threshold bars, four each side of the centre line
      for (float side : {-1.0f, 1.0f}) addMark(m, side * (0.22f + 0.24f * i), end * 6.1f, 0.14f, 1.1f);
    for (float side : {-1.0f, 1.0f})  // aiming-point blocks
      addMark(m, side * 0.55f, end * 3.9f, 0.3f, 1.2f);
  }
  for (int i = -3; i <= 3; ++i) addMark(m, 0.0f, 1.4f * static_cast<float>(i), 0.1f, 0.8f);  // centre dashes
  for (float side : {-1.0f, 1.0f})                                                           // edge lines
    addMark(m, side * 1.08f, 0.0f, 0.07f, 2.0f * kRunwayHalfLength - 0.2f);
  return m;
}

// A small aircraft, nose towards -z: fuselage, nose cone, wings, tailplane and fin.
Mesh makeAircraft() {
  const glm::mat4 alongZ = glm::rotate(glm::mat4(1), glm::radians(-90.0f), {1, 0, 0});  // +y to -z
  const auto box = [](glm::vec3 centre, glm::vec3 size) { return glm::scale(at(centre), size); };
  Mesh m;
  append(m, makeCylinder(0.11f, 1.2f, 16), alongZ);
  append(m, makeCone(0.11f, 0.3f, 16), at({0, 0, -0.75f}) * alongZ);
  append(m, makeCube(0.5f), box({0.0f, 0.0f, -0.1f}, {1.6f, 0.04f, 0.3f}));
  append(m, makeCube(0.5f), box({0.0f, 0.0f, 0.5f}, {0.6f, 0.04f, 0.18f}));
  append(m, makeCube(0.5f), box({0.0f, 0.15f, 0.5f}, {0.04f, 0.3f, 0.2f}));
  return m;
}

// ---- the lesson: options, variants, camera -------------------------------------------------------

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "06-coplanar-decals";
  info.title = "Co-planar decals";
  info.summary =
      "Runway markings and a projected shadow drawn exactly on the runway: z-fighting with the\n"
      "depth test, polygon offset, and the stencil recipe that needs no depth comparison at all.";
  info.options = {
      {"method", 'M', "decals by: 0 stencil tag, 1 depth test, 2 polygon offset, 3 depth test off", Stencil,
       3},
      {"decals", 'D', "draw the markings and the shadow at all (off: the bare runway, for the tests)", 1},
  };
  info.variants = {
      {"stencil", "Kilgard's recipe: decals with the depth test off, only on the tagged runway", {}},
      {"z-fighting",
       "decals with the plain depth test: they fight the runway pixel by pixel",
       {{"method", DepthTest}}},
      {"polygon-offset",
       "glPolygonOffset pulls each decal layer towards the eye: the usual fix",
       {{"method", PolygonOffset}}},
      {"depth-off",
       "depth test off and no stencil: the markings paint over the tower",
       {{"method", DepthOff}}},
  };
  info.passes = {"scenery", "runway", "decals", "shadow", "objects"};
  info.camera.distance = 11.0f;
  info.camera.azimuthDeg = 30.0f;
  info.camera.elevationDeg = 24.0f;
  info.camera.target = {0.0f, 0.0f, 1.0f};
  info.camera.farPlane = 30.0f;  // the grass ends at the far plane: a straight horizon
  return info;
}

}  // namespace

int main(int argc, char** argv) {
  return runLesson(
      lessonInfo(), [] { return std::make_unique<CoplanarDecals>(); }, argc, argv);
}
