// Lesson 09: shadow volumes of planar cut-outs (Kilgard, "Improving Shadows and Reflections via
// the Stencil Buffer", sections 6.2.1-6.2.2, and "Accelerated Stencil Shadow Extrusion via
// Vertex Blending").
//
// A cut-out is flat: a logo, a window lattice with holes. Seen from any light off its plane its
// silhouette is simply its border, the outline and the holes, so its shadow volume always has
// the same sides and only their far ends move with the light. That allows three extrusions:
//   cpu     the border edges extruded away from the light on the CPU every frame;
//   matrix  a static prism (the border pushed one unit down) bent into the volume by one
//           constant projective matrix, found from five point correspondences;
//   gpu     every border vertex stored twice, w = 1 and w = 0, and a vertex shader blending two
//           matrices: the model matrix for one copy, the model matrix times an extrusion to
//           infinity for the other.
// A complex object becomes a cut-out too: flattened onto a plane beyond it, its silhouette's
// outline (nonzero winding) is extruded from there. And lesson 04/05's planar shadow mixes in,
// as in the paper's figure 14: the logo shadows the teapot, the teapot shadows the floor.
//
// Stencil recipe (as lessons 07 and 08): the scene lit; the volumes counted with colour and depth
// writes off, depth test LESS (z-pass), INCR_WRAP on front faces and DECR_WRAP on back faces;
// then the scene again with the light off where the count is not zero, depth func EQUAL.

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>

#include "geometry/adjacency.h"
#include "geometry/cutout.h"
#include "geometry/planar.h"
#include "geometry/shadow_volume.h"
#include "geometry/shapes.h"
#include "geometry/weld.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/light_marker.h"
#include "gl/shader.h"

using namespace stencil;

namespace {

constexpr GLuint kCount = 0x7F;        // the shadow count, wrapping within the low seven bits
constexpr GLint kGroundTag = 0x80;     // the top bit: visible ground, for the planar shadow
constexpr float kFlatHeight = 0.2f;    // the plane the teapot is flattened onto, just above the floor
constexpr float kMatrixReach = 60.0f;  // how far the matrix pushes away from a directional light
constexpr glm::vec3 kAmbient{0.3f};
constexpr glm::vec4 kMarkerColour{1.0f, 0.95f, 0.4f, 1.0f};

// What one object needs: its mesh as drawn, and as a caster (welded, its edges' faces).
struct Caster {
  Mesh drawn;
  PreparedCaster prepared;
  explicit Caster(Mesh mesh) : drawn(std::move(mesh)), prepared(prepareCaster(drawn)) {}
};

Mesh makeTeapot();  // the scene's teapot, built after the lesson

class CutoutExtrusion final : public Lesson {
 public:
  CutoutExtrusion()
      : light_("common/light.vert", "common/light.frag"),
        volume_("common/volume.vert", "common/flat.frag"),
        blend_("09-cutout-extrusion/blend_extrude.vert", "common/flat.frag"),
        planar_("common/projected_shadow.vert", "common/flat.frag"),
        groundMesh_(makePlane(3.0f, 1)),
        teapot_(makeTeapot()),
        ground_(groundMesh_),
        marker_(0.06f, 12, 6),
        teapotGpu_(teapot_.drawn) {}

  void render(Frame& f) override {
    prepare(f);
    const glm::vec4 light = lightAt(f);

    // ---- the scene, lit --------------------------------------------------------------------
    glClearColor(0.55f, 0.65f, 0.8f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);                     // nearest surface wins, as always
    glEnable(GL_STENCIL_TEST);                   // the stencil holds the shadow count
    glStencilFunc(GL_ALWAYS, kGroundTag, 0xFF);  // the reference is the ground's tag...
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);      // ...written only in figure 14 (drawScene)
    drawScene(f, light, true, f.option("teapot") == kPlanar);
    if (light.w != 0.0f) marker_.draw(f.projection * f.view, glm::vec3(light), kMarkerColour);
    f.pass("lit");
    if (!f.on("shadow")) return;

    // ---- count the volumes in front of each visible surface (z-pass) ------------------------
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // the volumes are invisible
    glDepthMask(GL_FALSE);                                // and are not surfaces
    glDepthFunc(GL_LESS);                                 // only their parts in front of the scene
    glStencilMask(kCount);                                // the count keeps off the ground's tag bit
    glStencilFunc(GL_ALWAYS, 0, 0xFF);            // every volume face counts, whatever the stencil holds
    glEnable(GL_CULL_FACE);                       // one face orientation per pass
    glCullFace(GL_BACK);                          // front faces: the eye ray enters a volume
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR_WRAP);  // wraps, so the order of faces does not matter
    drawVolumes(f);
    glCullFace(GL_FRONT);                         // back faces: the eye ray leaves it
    glStencilOp(GL_KEEP, GL_KEEP, GL_DECR_WRAP);  // leaving decrements: zero again outside every volume
    drawVolumes(f);
    glCullFace(GL_BACK);                              // GL's default again
    glDisable(GL_CULL_FACE);                          // the scene is drawn with its own culling
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);  // colour back on for the unlit pass
    f.pass("count");

    // ---- the scene again with the light off, where the count is not zero ---------------------
    glDepthFunc(GL_EQUAL);                   // exactly the visible surfaces (invariant positions)
    glStencilFunc(GL_NOTEQUAL, 0, kCount);   // inside at least one volume
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);  // the count stays as the oracle reads it
    drawScene(f, light, false, false);
    f.pass("unlit");

    // ---- figure 14: the teapot's planar shadow on the floor (lesson 05's blocking recipe) ----
    if (f.option("teapot") == kPlanar) {
      glStencilMask(0xFF);                                  // the tag bit is written from here on
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // mark only
      glDisable(GL_DEPTH_TEST);                             // the tag says where the ground is visible
      glStencilFunc(GL_EQUAL, kGroundTag, 0xFF);            // visible ground not yet in a volume's shadow,
      glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);               // marked once: tag -> tag + 1
      glEnable(GL_CULL_FACE);                               // one layer of teapot is enough
      drawPlanarShadow(f, light);
      glDisable(GL_CULL_FACE);                          // back to the scene's own culling
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);  // colour back on
      glStencilFunc(GL_EQUAL, kGroundTag + 1, 0xFF);    // the marked ground, without the light
      glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);           // the mark stays for the oracle
      drawGround(f, light, false);
      glEnable(GL_DEPTH_TEST);  // back to the depth test for what follows
      f.pass("planar");
    }
    glDepthFunc(GL_LESS);  // GL's defaults again for the next frame's passes
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);

    // ---- the volumes themselves, translucent, for the classroom -----------------------------
    if (f.on("volumes")) {
      glDisable(GL_STENCIL_TEST);  // drawn over the result, the stencil stays the shadow's
      glEnable(GL_BLEND);          // translucent volumes over the scene
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      glDepthMask(GL_FALSE);  // every layer shows
      drawVolumes(f, glm::vec4(1.0f, 0.9f, 0.2f, 0.18f));
      glDepthMask(GL_TRUE);  // depth writes back on
      glDisable(GL_BLEND);
      f.pass("volumes");
    }
  }

 private:
  static constexpr int kCpu = 0, kMatrix = 1, kGpu = 2;
  static constexpr int kNone = 0, kFlattened = 1, kPlanar = 2;
  static constexpr glm::vec3 kSphereCentre{0.3f, 1.2f, 0.25f};
  static constexpr float kSphereRadius = 0.6f;

  // ---- the volumes ------------------------------------------------------------------------

  // Everything that depends on the options (the lattice, the sphere) is made when they change;
  // everything that depends on the light is made here each frame.
  void prepare(const Frame& f) {
    const int holes = f.option("holes");
    if (!logo_ || holes != logoHoles_) {
      logoHoles_ = holes;
      const std::vector<std::string> rows = latticeRows(holes);
      logo_ = std::make_unique<Caster>(makeCutout(rows, 1.8f / static_cast<float>(rows.size())));
      logoGpu_ = std::make_unique<GpuMesh>(logo_->drawn);
      // Static geometry, built once: the prism for the matrix, the doubled border for the GPU.
      prism_.upload(cutoutPrism(logo_->prepared.mesh, logo_->prepared.adjacency).vertices);
      const glm::vec4 fromAbove(0, 1, 0, 0);  // any light above: a cut-out's border is its silhouette
      doubled_.upload(doubledVertexVolume(
          logo_->prepared.mesh,
          possibleSilhouetteEdges(logo_->prepared.adjacency, facesLight(logo_->prepared.mesh, fromAbove))));
    }
    const int slices = f.option("slices");
    if (!sphere_ || slices != sphereSlices_) {
      sphereSlices_ = slices;
      sphere_ = std::make_unique<Caster>(makeSphere(kSphereRadius, slices, std::max(2, slices / 2)));
      sphereGpu_ = std::make_unique<GpuMesh>(sphere_->drawn);
    }

    const glm::vec4 light = lightAt(f);
    // The light in the cut-out's own space, where its plane is y = 0. In that plane (edge-on, or
    // a directional light parallel to it) the cut-out has no volume: it casts nothing.
    logoLight_ = glm::inverse(logoModel(f)) * light;
    if (logoLight_.w != 0.0f) logoLight_ /= logoLight_.w;
    const float scale = logoLight_.w != 0.0f ? 1.0f : glm::length(glm::vec3(logoLight_));
    logoEdgeOn_ = std::abs(logoLight_.y) <= 1e-4f * scale;
    if (f.on("logo") && !logoEdgeOn_ && f.option("method") == kCpu) {
      const float distance =
          f.option("distance") == 0 ? kInfinity : 0.1f * static_cast<float>(f.option("distance"));
      logoVolume_.upload(
          silhouetteVolume(logo_->prepared.mesh, logo_->prepared.adjacency, logoLight_, distance).vertices);
    }
    if (f.on("logo") && !logoEdgeOn_ && f.option("method") == kMatrix)
      logoMatrix_ = cutoutExtrusionMatrix(logoLight_, kMatrixReach);  // one matrix per light position

    // The teapot (or sphere) flattened onto the plane y = kFlatHeight: its silhouette projected
    // there, the outline of the nonzero-winding region, extruded away from the light.
    if (f.option("teapot") == kFlattened) {
      const Caster& object = f.on("sphere") ? *sphere_ : teapot_;
      const glm::mat4 model = objectModel(f);
      const glm::vec4 objectLight = glm::inverse(model) * light;
      const glm::vec4 plane = glm::transpose(model) * glm::vec4(0, 1, 0, -kFlatHeight);  // in its own space
      const std::vector<Segment> outline = nonzeroOutline(
          projectedSilhouette(object.prepared.mesh, object.prepared.adjacency, objectLight, plane), plane);
      objectVolume_.upload(flattenedVolume(outline, objectLight, kInfinity).vertices);
    }
  }

  // Every volume once, with the stencil state the caller set; a colour to see them.
  void drawVolumes(const Frame& f, glm::vec4 colour = glm::vec4(0)) {
    const glm::mat4 viewProjection = f.projection * f.view;
    if (f.on("logo") && !logoEdgeOn_) {
      const glm::mat4 toClip = viewProjection * logoModel(f);
      // The static prism and doubled border are wound for a light above the cut-out's front;
      // from behind it the same triangles face into the volume.
      if (logoLight_.y < 0.0f && f.option("method") != kCpu) glFrontFace(GL_CW);
      switch (f.option("method")) {
        case kCpu:
          volume_.set("colour", colour);
          volume_.set("transform", toClip);
          logoVolume_.draw();
          break;
        case kMatrix:
          volume_.set("colour", colour);
          volume_.set("transform", toClip * logoMatrix_);  // static geometry, one constant matrix
          prism_.draw();
          break;
        case kGpu:
          blend_.set("colour", colour);
          blend_.set("nearTransform", toClip);
          blend_.set("farTransform", toClip * extrusionToInfinity(logoLight_));
          doubled_.draw();
          break;
      }
      glFrontFace(GL_CCW);
    }
    if (f.option("teapot") == kFlattened) {
      volume_.set("colour", colour);
      volume_.set("transform", viewProjection * objectModel(f));
      objectVolume_.draw();
    }
  }

  // ---- the scene ---------------------------------------------------------------------------

  static glm::mat4 logoModel(const Frame& f) {
    glm::mat4 m = glm::translate(glm::mat4(1), {-0.35f, 2.5f, -0.1f});
    m = glm::rotate(m, 0.3f, glm::normalize(glm::vec3(1, 0, 0.5f)));       // tilted: no axis-aligned luck
    return glm::rotate(m, 0.15f * static_cast<float>(f.time), {0, 1, 0});  // spins in its plane
  }

  static glm::mat4 teapotModel(const Frame& f) {
    return glm::rotate(glm::translate(glm::mat4(1), {0.3f, 1.05f, 0.25f}),
                       0.3f * static_cast<float>(f.time) + 0.6f, {0, 1, 0});
  }

  static glm::mat4 objectModel(const Frame& f) {
    return f.on("sphere") ? glm::translate(glm::mat4(1), kSphereCentre) : teapotModel(f);
  }

  // Homogeneous: w = 1 a point light, w = 0 the direction towards a directional light.
  static glm::vec4 lightAt(const Frame& f) {
    const float a = 0.4f * static_cast<float>(f.time) + 0.5f;
    const glm::mat4 logo = logoModel(f);
    switch (f.option("light")) {
      case 1:
        return {glm::normalize(glm::vec3(-0.45f + 0.2f * std::cos(a), 1.0f, -0.45f + 0.2f * std::sin(a))),
                0.0f};
      case 2:  // 0.3 above the lattice's centre, circling a little
        return logo * glm::vec4(0.15f * std::cos(a), 0.3f, 0.15f * std::sin(a), 1.0f);
      case 3:  // a direction in the lattice's plane (y = 0 in its space), as steep as the plane allows
        return logo * glm::vec4(steepestInPlane(logo), 0.0f);
      case 4:  // a point in the lattice's plane, 1.6 from its centre on its high side
        return logo * glm::vec4(1.6f * steepestInPlane(logo), 1.0f);
      default: return {1.1f * std::cos(a), 4.6f, 1.1f * std::sin(a), 1.0f};
    }
  }

  // The unit direction in the cut-out's plane (its own x-z) that climbs fastest in the world.
  static glm::vec3 steepestInPlane(const glm::mat4& logo) {
    const glm::vec3 up = glm::transpose(glm::mat3(logo)) * glm::vec3(0, 1, 0);  // world up in its space
    return glm::normalize(glm::vec3(up.x, 0.0f, up.z));
  }

  void setLight(const Frame& f, glm::vec4 light, bool on) {
    light_.set("viewProjection", f.projection * f.view);
    light_.set("ambient", kAmbient);
    light_.set("light", light);
    // A directional light does not fall off with distance: dimmer, so the ground is not white.
    const glm::vec3 colour = light.w != 0.0f ? glm::vec3(1.1f, 1.05f, 0.95f) : glm::vec3(0.75f, 0.72f, 0.65f);
    light_.set("lightColour", on ? colour : glm::vec3(0.0f));
    light_.set("eye", f.eye);
  }

  // The whole scene with the light on or off. tagGround: the visible ground gets the tag bit.
  void drawScene(const Frame& f, glm::vec4 light, bool on, bool tagGround) {
    setLight(f, light, on);
    glEnable(GL_CULL_FACE);  // the teapot and sphere are closed
    light_.set("model", objectModel(f));
    light_.set("colour", glm::vec3(0.85f, 0.45f, 0.25f));
    light_.set("shininess", 40.0f);
    (f.on("sphere") ? *sphereGpu_ : teapotGpu_).draw();
    glDisable(GL_CULL_FACE);  // the cut-out and the ground are seen from both sides
    if (f.on("logo")) {
      light_.set("model", logoModel(f));
      light_.set("colour", glm::vec3(0.25f, 0.45f, 0.8f));
      light_.set("shininess", 20.0f);
      logoGpu_->draw();
    }
    if (tagGround) {
      glStencilMask(kGroundTag);                  // only the tag bit
      glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);  // drawn last: only where the ground is visible
    }
    drawGround(f, light, on);
    glStencilMask(0xFF);                     // every later draw writes all bits again
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);  // and nothing until told
  }

  void drawGround(const Frame& f, glm::vec4 light, bool on) {
    setLight(f, light, on);
    light_.set("model", glm::mat4(1));
    light_.set("colour", glm::vec3(0.78f, 0.78f, 0.72f));
    light_.set("shininess", 16.0f);
    ground_.draw();
  }

  // Lesson 04's flattened teapot, clipped to the slab between the floor and the light.
  void drawPlanarShadow(const Frame& f, glm::vec4 light) {
    const glm::vec4 floor = planeFrom({0, 0, 0}, {0, 1, 0});
    planar_.set("model", teapotModel(f));
    planar_.set("shadowMatrix", planarShadowMatrix(floor, light));
    planar_.set("viewProjection", f.projection * f.view);
    planar_.set("receiver", floor);
    planar_.set("light", light);
    planar_.set("colour", glm::vec4(0));
    glEnable(GL_CLIP_DISTANCE0);  // only around the one shader that writes clip distances
    glEnable(GL_CLIP_DISTANCE1);
    teapotGpu_.draw();
    glDisable(GL_CLIP_DISTANCE0);
    glDisable(GL_CLIP_DISTANCE1);
  }

  Program light_, volume_, blend_, planar_;
  Mesh groundMesh_;  // kept for the oracle's ray cast
  Caster teapot_;
  std::unique_ptr<Caster> logo_, sphere_;
  int logoHoles_ = 0, sphereSlices_ = 0;
  GpuMesh ground_;
  LightMarker marker_;
  GpuMesh teapotGpu_;
  std::unique_ptr<GpuMesh> logoGpu_, sphereGpu_;
  GpuTriangles logoVolume_, prism_, doubled_, objectVolume_;
  glm::vec4 logoLight_{0.0f};
  glm::mat4 logoMatrix_{1.0f};
  bool logoEdgeOn_ = false;

  // ---- test hooks ---------------------------------------------------------------------------------

 public:
  // The count's zero is a lit receiver. Which objects cast and receive follows the options: an
  // object casts only where the lesson builds its shadow, and an object that casts its own
  // shadow is not judged as a receiver (the lesson does not shadow it by itself).
  std::optional<ShadowCheck> shadowCheck(const Frame& f) const override {
    if (!f.on("shadow")) return std::nullopt;
    const bool objectCasts = f.option("teapot") != kNone;
    ShadowCheck check{{{&groundMesh_, glm::mat4(1), false, true}},
                      lightAt(f),
                      [](std::uint8_t s) { return (s & kCount) == 0; },
                      true};
    if (f.on("logo")) check.objects.push_back({&logo_->drawn, logoModel(f), true, false});
    if (!f.on("sphere"))
      check.objects.push_back({&teapot_.drawn, teapotModel(f), objectCasts, !objectCasts});
    else if (f.on("analytic"))
      check.objects.push_back(
          {nullptr, glm::mat4(1), objectCasts, !objectCasts, glm::vec4(kSphereCentre, kSphereRadius)});
    else
      check.objects.push_back(
          {&sphere_->drawn, glm::translate(glm::mat4(1), kSphereCentre), objectCasts, !objectCasts});
    if (check.light.w != 0.0f)
      check.objects.push_back(
          {&marker_.mesh(), glm::translate(glm::mat4(1), glm::vec3(check.light)), false, false});
    return check;
  }
};

// ---- the teapot --------------------------------------------------------------------------------------

// The meshes of one closed object as one mesh (they may intersect: the stencil counts layers).
Mesh append(Mesh to, const Mesh& part, const glm::mat4& model) {
  const Mesh t = transformed(part, model);
  const auto base = static_cast<std::uint32_t>(to.positions.size());
  to.positions.insert(to.positions.end(), t.positions.begin(), t.positions.end());
  to.normals.insert(to.normals.end(), t.normals.begin(), t.normals.end());
  for (const std::uint32_t i : t.indices) to.indices.push_back(base + i);
  return to;
}

// A teapot from the shapes: a squat body, a spout, a handle, a lid and its knob.
Mesh makeTeapot() {
  using glm::rotate, glm::scale, glm::translate;
  const glm::mat4 id(1.0f);
  Mesh m = append({}, makeSphere(0.55f, 40, 20), scale(id, {1.0f, 0.8f, 1.0f}));
  m = append(m, makeCone(0.14f, 0.75f, 24),
             rotate(translate(id, {0.6f, 0.1f, 0}), glm::radians(-55.0f), {0, 0, 1}));
  m = append(m, makeTorus(0.27f, 0.06f, 32, 12),
             rotate(translate(id, {-0.55f, 0.05f, 0}), glm::radians(90.0f), {1, 0, 0}));
  m = append(m, makeCylinder(0.26f, 0.1f, 32), translate(id, {0, 0.44f, 0}));
  return append(m, makeSphere(0.08f, 16, 8), translate(id, {0, 0.54f, 0}));
}

// ---- the lesson: options, variants, camera -------------------------------------------------------

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "09-cutout-extrusion";
  info.title = "Cut-out extrusion";
  info.summary =
      "A planar cut-out's shadow volume extruded on the CPU, by one projective matrix, and on the GPU\n"
      "from doubled vertices; a complex object flattened into a cut-out; planar shadows mixed in.";
  info.options = {
      {"method", 'M',
       "the cut-out's volume: 0 CPU each frame, 1 projective matrix on a static prism, 2 GPU doubled "
       "vertices",
       0, 2},
      {"light", 'L',
       "0 point light above, 1 directional, 2 point light close above the cut-out, 3 directional light\n"
       "      parallel to the cut-out, 4 point light in the cut-out's plane",
       0, 4},
      {"distance", 'X', "CPU extrusion distance in tenths (0: to infinity, w = 0)", 0, 60},
      {"logo", 'O', "the cut-out (a window lattice) above the scene", 1},
      {"holes", 'N', "holes per row of the lattice", 3, 16, 1},
      {"teapot", 'T',
       "the teapot's own shadow: 0 none, 1 flattened into a cut-out silhouette, 2 planar (figure 14)", 0, 2},
      {"sphere", 'Y', "a sphere instead of the teapot", 0},
      {"slices", 'I', "the sphere's slices (stacks: half as many)", 24, 256, 3},
      {"analytic", 'A', "--oracle judges against the true sphere, not its mesh", 0},
      {"volumes", 'W', "draw the shadow volumes translucently", 0},
      {"shadow", 'H', "shadows at all (off: everything lit)", 1},
  };
  info.variants = {
      {"cpu", "the lattice's border extruded to infinity on the CPU each frame", {}},
      {"matrix", "a static prism bent into the volume by one projective matrix", {{"method", 1}}},
      {"gpu", "doubled vertices (w = 1, w = 0) extruded by a blended pair of matrices", {{"method", 2}}},
      {"directional", "a directional light, extruded on the CPU", {{"light", 1}}},
      {"directional-matrix",
       "a directional light: the matrix can only push a finite reach",
       {{"light", 1}, {"method", 1}}},
      {"directional-gpu",
       "a directional light on the GPU: every far vertex the same point at infinity",
       {{"light", 1}, {"method", 2}}},
      {"close-light", "a light just above the cut-out: the volume spreads almost flat", {{"light", 2}}},
      {"close-light-short",
       "the same light and a volume only one unit long: it ends in the air, the count is wrong",
       {{"light", 2}, {"distance", 10}}},
      {"parallel", "a directional light parallel to the cut-out: no volume, no shadow", {{"light", 3}}},
      {"parallel-matrix",
       "the same with the matrix: the five points are coplanar, no matrix",
       {{"light", 3}, {"method", 1}}},
      {"edge-on", "a point light in the cut-out's plane: edge-on, no shadow", {{"light", 4}}},
      {"edge-on-gpu", "the same on the GPU", {{"light", 4}, {"method", 2}}},
      {"flatten", "the teapot flattened into a cut-out silhouette above the floor", {{"teapot", 1}}},
      {"figure-14",
       "the logo's volume on the teapot, the teapot's planar shadow on the floor",
       {{"teapot", 2}}},
      {"sphere",
       "a sphere of 24 slices flattened into a cut-out",
       {{"logo", 0}, {"teapot", 1}, {"sphere", 1}}},
      {"volumes", "the volumes drawn translucently over the result", {{"teapot", 1}, {"volumes", 1}}},
  };
  info.shadows = true;
  info.passes = {"lit", "count", "unlit", "planar", "volumes"};
  info.camera.distance = 7.5f;
  info.camera.azimuthDeg = 35.0f;
  info.camera.elevationDeg = 30.0f;
  info.camera.target = {0.0f, 0.8f, 0.0f};
  return info;
}

}  // namespace

int main(int argc, char** argv) {
  return runLesson(
      lessonInfo(), [] { return std::make_unique<CutoutExtrusion>(); }, argc, argv);
}
