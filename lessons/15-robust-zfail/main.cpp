// Lesson 15: robust shadow volumes with z-fail (Everitt and Kilgard, "Practical and Robust
// Stenciled Shadow Volumes for Hardware-Accelerated Rendering").
//
// Lesson 08's z-pass counts the volume faces in front of the visible surface, so it breaks
// when the eye is inside a volume or the near plane cuts one. Z-fail counts the faces *behind*
// the surface instead: +1 for every back face that fails the depth test (the ray leaves a
// volume beyond the surface), -1 for every front face that fails it. Behind the surface there
// is no eye and no near plane, so the count is right wherever it is taken, provided that
//   - every volume is closed: the silhouette's sides, the caster's lit faces as the light cap
//     and its unlit faces pushed away from the light as the dark cap (closedVolume); so the
//     casters must be closed, two-manifold, consistently wound meshes (prepareCaster checks);
//   - nothing clips the volumes behind the surface: the far plane goes to infinity (Pinf,
//     glm::infinitePerspective), the volumes are pushed to infinity (w = 0, which needs w >= 0
//     everywhere and an ideal light: a point or a direction), and Pinf loses only n/f of the
//     depth range. Or the far plane stays finite and depth clamping keeps what lies beyond it.
// Where the driver has clip control (core in GL 4.5) the depth buffer is a float and the depth
// reversed: 1 at the near plane, n/d at distance d, 0 at infinity. A 24-bit buffer with GL's
// mapping 1 - n/d has steps of d^2/n * 2^-24 units, too coarse for a small near plane; a float
// holding n/d keeps about 2^-24 of d at every distance. The variant pinf-fixed24 keeps the old path.
// One pass with two-sided stencil and wrapping counts both kinds of faces; the casters' sides
// turned from the light, which the count puts in their own volumes, are then marked shadowed
// outright (markTurnedFromLight: near the terminator the sides run within rounding of them). Each
// light then adds its light where its stencil is zero, over one ambient pass. The scene is a Scene
// (geometry/scene.h): the one built in below, or one read from a file with --scene.

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <string>

#include "geometry/bounds.h"
#include "geometry/scene.h"
#include "geometry/shadow_volume.h"
#include "geometry/shapes.h"
#include "gl/depth_mapping.h"
#include "gl/errors.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/light_shading.h"
#include "gl/shader.h"

using namespace stencil;

namespace {

Scene builtInScene();  // defined after the lesson

// The paper's requirements, checked once: closed, two-manifold, consistently wound casters
// (prepareCaster's report) and model matrices that keep w >= 0 (affine). One line if not.
void checkRequirements(const Scene& scene) {
  for (const SceneObject& o : scene.objects) {
    // An object from a file is named by its line there, as the file's other errors are.
    const std::string where =
        scene.file.empty() ? "" : scene.file.string() + ":" + std::to_string(o.line) + ": ";
    const glm::vec4 lastRow(o.model[0][3], o.model[1][3], o.model[2][3], o.model[3][3]);
    if (lastRow != glm::vec4(0, 0, 0, 1))
      throw UsageError(where + "object '" + o.name +
                       "': its model matrix is projective; shadow volumes need w >= 0");
    if (!o.casts || o.caster.report.closedManifold()) continue;
    // Non-manifold and inconsistent casters are refused when the file is read; open ones are left.
    throw UsageError(
        where + "caster '" + o.name + "' is open (" + std::to_string(o.caster.report.borderEdges) +
        " border edges) and cannot bound a closed shadow volume; z-fail here needs closed casters"
        " (lesson 16 takes open ones)");
  }
}

class RobustZFail final : public Lesson {
 public:
  // The scene from --scene, or the built-in one.
  explicit RobustZFail(const Scene* fromFile)
      : owned_(fromFile ? Scene{} : builtInScene()),
        scene_(fromFile ? *fromFile : owned_),
        fromFile_(fromFile != nullptr),
        light_("common/light.vert", "common/light.frag"),
        volume_("15-robust-zfail/volume.vert", "common/flat.frag") {
    checkRequirements(scene_);
    for (const SceneObject& o : scene_.objects) {
      gpu_.push_back(std::make_unique<GpuMesh>(o.mesh));
      const bool closed = o.casts && o.caster.report.closedManifold();
      convex_.push_back(closed && isConvex(o.caster.mesh, o.caster.adjacency));
      casterBounds_.push_back(closed ? boundingSphereOf(o.caster.mesh.positions) : BoundingSphere{});
    }
  }

  void render(Frame& f) override {
    // 0. The depth mapping, before anything is cleared or drawn. Reversed (Frame::reversedDepth):
    // window depth is clip z / w with no remapping, 1 at the near plane and n/d at distance d,
    // which the float depth buffer holds to about 2^-24 of d at every distance. Every depth test
    // and the projection follow it (gl/depth_mapping.h).
    depth_ = depthMappingOf(f);
    if (f.reversedDepth) glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // no 0.5 + 0.5 z/w
    glClearDepth(depth_.farthest);                                      // 0 reversed: infinity
    glClearColor(0.1f, 0.1f, 0.13f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);  // depth: the farthest
    const std::vector<glm::mat4> models = modelsAt(f.time);
    const std::vector<ShiningLight> lights = lightsInOrder(f);
    f.count("lights_buried", 0);  // in --stats in every frame, buried lights or none
    mirroredView_ = glm::determinant(glm::mat3(f.view)) < 0.0f;
    // Rooms: a closed caster around the eye is a shell seen from inside (geometry/solid.h).
    solids_ = solidsSeenFrom(scene_, models, f.eye);
    if (!solids_.refusal.empty()) throw UsageError(solids_.refusal);

    // 1. Ambient light everywhere, filling the depth buffer that every later pass tests against.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(depth_.less);  // the nearest surface wins
    // Both sides: where the near plane cuts into a closed object, its inside shows, as the
    // oracle's ray cast sees it (culled, the background would show through it).
    glDisable(GL_CULL_FACE);
    drawScene(f, models, scene_.ambient, glm::vec4(0, 1, 0, 0), glm::vec3(0), kInfinity);
    f.pass("ambient");

    for (std::size_t i = 0; i < lights.size(); ++i) {
      buildVolumes(f, models, lights[i].light.position, i);
      const std::string which = "light " + std::to_string(lights[i].index);  // the passes say whose they are
      if (f.on("shadow") && lightBuried(scene_, models, solids_, lights[i].light.position)) {
        // A light inside a solid (outside the room the eye is in) lights nothing the eye sees:
        // its picture is all shadow, a count of 1 everywhere, and it adds no light.
        glClearStencil(1);
        glClear(GL_STENCIL_BUFFER_BIT);
        glClearStencil(0);
        f.count("lights_buried");
        f.pass("volumes", which);
        f.shadowMask("light-" + std::to_string(lights[i].index));
        f.pass("lit", which);
        continue;
      }
      if (f.on("shadow")) {
        // 2. Count this light's volumes. The stencil starts at zero for each light.
        glClear(GL_STENCIL_BUFFER_BIT);
        glEnable(GL_STENCIL_TEST);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // the stencil only
        glDepthMask(GL_FALSE);                                // the volumes are not surfaces
        glDisable(GL_CULL_FACE);  // front and back faces of the volumes in one pass
        glStencilFunc(GL_ALWAYS, 0, 0xFF);
        if (f.on("zpass")) {
          // In front of the surface: a front face is an entry, a back face an exit.
          glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
          glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
        } else {
          // Behind the surface (the depth test fails): a back face is an exit still to come, a
          // front face an entry; wrapping makes their order irrelevant.
          glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
          glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
        }
        if (f.on("depth-clamp"))
          glEnable(GL_DEPTH_CLAMP);  // beyond the far plane: the far depth, not clipped
        const CountPlan plan = countPlan(pieceBounds(i));
        if (!plan.fold) {
          drawVolumes(f, i, glm::vec4(0));
        } else {
          // More than 255 nested volumes could wrap the count to 0 (lit). Count in groups that
          // cannot pass 127, in the low 7 bits, and fold each group into bit 7: shadowed.
          for (int g = 0; g < plan.groups; ++g) {
            glStencilMask(0x7F);  // bit 7 keeps what the groups before found
            drawVolumes(f, i, glm::vec4(0), &plan, g);
            foldCount(f.on("zpass"));
          }
          glStencilMask(0xFF);
          f.count("count_groups", static_cast<std::uint64_t>(plan.groups));
        }
        glDisable(GL_DEPTH_CLAMP);
        // The old 24-bit path (pinf-fixed24, or no clip control) keeps the count alone.
        if (f.on("mark") && f.reversedDepth) markTurnedFromLight(f, models, lights[i].light.position);
        f.pass("volumes", which);
        f.shadowMask("light-" + std::to_string(lights[i].index));  // under --mask-out: this light's mask

        // 3. This light, added where its count is zero.
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glStencilFunc(GL_EQUAL, 0, 0xFF);  // outside every volume of this light
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
      }
      glDepthFunc(GL_EQUAL);  // exactly the visible surfaces of pass 1
      glEnable(GL_BLEND);
      glBlendFunc(GL_ONE, GL_ONE);  // lights add up
      drawScene(f, models, glm::vec3(0), lights[i].light.position, lights[i].light.colour,
                lights[i].light.radius);
      glDisable(GL_BLEND);
      glDisable(GL_STENCIL_TEST);
      glDepthFunc(depth_.less);
      f.pass("lit", which);
    }
    glDepthMask(GL_TRUE);

    if (f.on("show")) showVolumes(f, lights);
    glFrontFace(GL_CCW);
  }

 private:
  std::vector<glm::mat4> modelsAt(double time) const {
    std::vector<glm::mat4> models;
    for (const SceneObject& o : scene_.objects) models.push_back(o.modelAt(time));
    return models;
  }

  // A light that shines this frame, and its index in the scene (for its mask's name).
  struct ShiningLight {
    std::size_t index;
    SceneLight light;
  };

  // The shining lights, the one named by "last" moved to the end.
  std::vector<ShiningLight> lightsInOrder(const Frame& f) const {
    const auto wanted = fromFile_ ? std::size_t{0} : static_cast<std::size_t>(f.option("lights"));
    const std::size_t n = wanted == 0 ? scene_.lights.size() : std::min(wanted, scene_.lights.size());
    std::vector<ShiningLight> lights;
    for (std::size_t i = 0; i < n; ++i) lights.push_back({i, scene_.lights[i]});
    if (f.on("directional")) lights[0].light.position = glm::vec4(0.3f, 1.0f, 0.5f, 0.0f);
    const std::size_t last = std::min(static_cast<std::size_t>(f.option("last")), n - 1);
    std::rotate(lights.begin(), lights.begin() + static_cast<std::ptrdiff_t>(last + 1), lights.end());
    return lights;
  }

  // How far the volumes go. To infinity (w = 0) under a perspective projection. A parallel
  // projection maps w = 0 to clip w = 0, the line at infinity of the picture, and the dark cap
  // vanishes there; so push the volumes a finite way, past every point of the scene, and let
  // depth clamping keep their far ends beyond the far plane.
  float extrusionReach(const Frame& f, const std::vector<glm::mat4>& models, const glm::vec4& light) const {
    const bool parallel = f.projection[2][3] == 0.0f;  // clip w does not depend on depth
    if (!parallel) return kInfinity;
    std::vector<glm::vec3> points;
    for (std::size_t i = 0; i < scene_.objects.size(); ++i)
      for (const glm::vec3& p : scene_.objects[i].mesh.positions)
        points.push_back(models[i] * glm::vec4(p, 1));
    const BoundingSphere s = boundingSphereOf(points);
    if (light.w == 0.0f) return 2.0f * s.radius;  // from any point across the whole scene
    return glm::length(glm::vec3(light) / light.w - s.centre) + s.radius;  // past the farthest point
  }

  // Every caster's closed volume for one light, in the caster's own space.
  void buildVolumes(Frame& f, const std::vector<glm::mat4>& models, const glm::vec4& worldLight,
                    std::size_t lightIndex) {
    const float reach = extrusionReach(f, models, worldLight);
    std::size_t slot = lightIndex * scene_.objects.size();
    if (volumes_.size() < slot + scene_.objects.size()) volumes_.resize(slot + scene_.objects.size());
    if (pieces_.size() <= lightIndex) pieces_.resize(lightIndex + 1);
    std::vector<VolumePiece>& pieces = pieces_[lightIndex];
    pieces.clear();
    for (std::size_t i = 0; i < scene_.objects.size(); ++i, ++slot) {
      const SceneObject& o = scene_.objects[i];
      if (!volumes_[slot]) volumes_[slot] = std::make_unique<GpuTriangles>();
      // A room (convex, solidsSeenFrom checks) shadows nothing inside itself, where the eye and
      // an unburied light are: its volume would be its outside, which holds infinity.
      if (!o.casts || solids_.room[i]) {
        volumes_[slot]->upload({});
        continue;
      }
      const glm::vec4 light = glm::inverse(models[i]) * worldLight;
      const std::vector<bool> lit = facesLight(o.caster.mesh, light);
      const ClosedVolume v = closedVolume(o.caster.mesh, o.caster.adjacency, light, reach);
      f.count("silhouette_edges", v.possibleSilhouetteEdges);
      f.count("side_triangles", v.sideTriangles);
      f.count("light_cap_triangles", v.lightCapTriangles);
      f.count("dark_cap_triangles", v.darkCapTriangles);
      // How deep this volume can nest (geometry/shadow_volume.h): the face count, half the
      // silhouette, or the silhouette seen from the light, whichever is least. Past a group's
      // 127, the caster is counted in pieces of its light cap instead, each at most 127 deep.
      const BoundingSphere& b = casterBounds_[i];
      const bool outside = light.w == 0.0f || glm::distance(glm::vec3(light) / light.w, b.centre) > b.radius;
      std::size_t nesting = nestingBound(v.lightCapTriangles, v.possibleSilhouetteEdges, convex_[i], outside);
      if (nesting > 1)
        nesting = std::min(nesting, projectedNestingBound(o.caster.mesh, lit,
                                                          possibleSilhouetteEdges(o.caster.adjacency, lit), light));
      std::vector<ClosedVolume> parts;
      std::vector<std::size_t> partNesting;
      if (nesting <= 127) {
        parts.push_back(v);
        partNesting.push_back(nesting);
      } else {
        for (const LitPiece& piece : litFacePieces(o.caster.mesh, o.caster.adjacency, lit, light, 127)) {
          parts.push_back(closedVolume(o.caster.mesh, o.caster.adjacency, light, reach, piece.lit));
          partNesting.push_back(piece.nesting);
        }
        f.count("volume_pieces", parts.size());
      }
      std::vector<glm::vec4> vertices;
      for (std::size_t k = 0; k < parts.size(); ++k) {
        const ClosedVolume& part = parts[k];
        const auto first = static_cast<GLint>(vertices.size());
        // Without caps only the sides, which come first.
        const std::size_t triangles = f.on("caps") ? part.triangles.triangleCount() : part.sideTriangles;
        vertices.insert(vertices.end(), part.triangles.vertices.begin(),
                        part.triangles.vertices.begin() + static_cast<std::ptrdiff_t>(3 * triangles));
        pieces.push_back({i, first, static_cast<GLsizei>(3 * triangles), partNesting[k]});
      }
      volumes_[slot]->upload(vertices);
    }
    volumeModels_ = models;
  }

  // One light's volumes; with a plan, only the pieces of group `group`.
  void drawVolumes(const Frame& f, std::size_t lightIndex, glm::vec4 colour, const CountPlan* plan = nullptr,
                   int group = 0) {
    volume_.set("viewProjection", viewProjectionFrom(depth_.projection * f.view, drawingOrigin(f.eye)));
    volume_.set("origin", drawingOrigin(f.eye));
    volume_.set("colour", colour);
    const std::vector<VolumePiece>& pieces = pieces_[lightIndex];
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      if (plan && plan->group[k] != group) continue;
      const VolumePiece& p = pieces[k];
      volume_.set("model", volumeModels_[p.object]);
      frontFaceFor(volumeModels_[p.object]);
      volumes_[lightIndex * scene_.objects.size() + p.object]->draw(p.first, p.count);
    }
  }

  std::vector<std::size_t> pieceBounds(std::size_t lightIndex) const {
    std::vector<std::size_t> bounds;
    for (const VolumePiece& p : pieces_[lightIndex]) bounds.push_back(p.nesting);
    return bounds;
  }

  // A caster's side turned from the light, where the eye sees it, lies in the caster's own shadow:
  // the light reaches it through the caster. Its volume says so with a count of 1 or more, but
  // near the terminator, on faces a few hundredths or less from edge-on, the sides of the possible
  // silhouette run within a few millionths of the eye's distance behind the surface, and the
  // rasterizer's depths can round one in front of it: a pixel counted 0, lit. Bit 7 set where such
  // a face reads 0 (facesTurnedFromLight, decided per face as facesLight decides), at exactly its
  // depths (GL_EQUAL, the ambient pass's program), makes the rule hold whatever the count rounded to.
  void markTurnedFromLight(const Frame& f, const std::vector<glm::mat4>& models, const glm::vec4& worldLight) {
    const bool parallel = f.projection[2][3] == 0.0f;  // clip w does not depend on depth
    const glm::vec4 worldEye =
        parallel ? glm::vec4(glm::vec3(glm::inverse(f.view)[2]), 0.0f) : glm::vec4(f.eye, 1.0f);
    // Only where the count reads 0: bit 7 set there (INVERT through the mask), every other
    // count kept as it is.
    glStencilMask(0x80);
    glStencilFunc(GL_EQUAL, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);
    glDepthFunc(GL_EQUAL);
    setLightShading(light_, {.viewProjection = depth_.projection * f.view,
                             .origin = drawingOrigin(f.eye)});  // the ambient pass's positions
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
      const SceneObject& o = scene_.objects[i];
      if (!o.casts || solids_.room[i]) continue;  // a room shadows nothing inside itself
      const glm::mat4 toObject = glm::inverse(models[i]);
      Mesh turned{o.mesh.positions, o.mesh.normals,
                  facesTurnedFromLight(o.mesh, toObject * worldLight, toObject * worldEye)};
      if (turned.indices.empty()) continue;
      light_.set("model", models[i]);
      GpuMesh(turned).draw();
    }
    glDepthFunc(depth_.less);
    glStencilMask(0xFF);
  }

  // Where a group's count (bits 0-6) is not 0, the pixel is in a shadow: set bit 7 and clear the
  // count for the next group. A rectangle over the whole window, testing only the stencil; then
  // the counting state again.
  void foldCount(bool zpass) {
    glStencilMask(0xFF);
    glStencilFunc(GL_NOTEQUAL, 0x80, 0x7F);     // (0x80 & 0x7F) = 0 != count: counted something
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);  // 0x80: shadowed, count 0
    glDisable(GL_DEPTH_TEST);
    volume_.set("viewProjection", glm::mat4(1.0f));
    volume_.set("origin", glm::vec3(0.0f));
    volume_.set("model", glm::mat4(1.0f));
    glFrontFace(GL_CCW);
    window_.draw();
    glEnable(GL_DEPTH_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    if (zpass) {
      glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
      glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
    } else {
      glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
      glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
    }
  }

  // For the classroom: each light's volumes as translucent sheets in its colour, then the
  // silhouette edges they grow from as lines.
  void showVolumes(Frame& f, const std::vector<ShiningLight>& lights) {
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (std::size_t i = 0; i < lights.size(); ++i)
      drawVolumes(f, i, glm::vec4(lights[i].light.colour, 0.12f));
    glDisable(GL_BLEND);
    f.pass("show-volumes");

    std::vector<glm::vec4> segments;
    volume_.set("colour", glm::vec4(1.0f, 0.95f, 0.3f, 1.0f));
    glDepthFunc(depth_.lequal);  // on the casters' own edges
    for (std::size_t c = 0; c < scene_.objects.size(); ++c) {
      const SceneObject& o = scene_.objects[c];
      if (!o.casts) continue;
      segments.clear();
      for (const ShiningLight& l : lights) {
        const glm::vec4 light = glm::inverse(volumeModels_[c]) * l.light.position;
        for (const SilhouetteEdge& e :
             possibleSilhouetteEdges(o.caster.adjacency, facesLight(o.caster.mesh, light))) {
          segments.push_back(glm::vec4(o.caster.mesh.positions[e.v0], 1.0f));
          segments.push_back(glm::vec4(o.caster.mesh.positions[e.v1], 1.0f));
        }
      }
      silhouettes_.upload(segments);
      volume_.set("model", volumeModels_[c]);
      silhouettes_.draw();
    }
    glDepthFunc(depth_.less);
    glDepthMask(GL_TRUE);
    f.pass("silhouettes");
  }

  void drawScene(const Frame& f, const std::vector<glm::mat4>& models, glm::vec3 ambient, glm::vec4 light,
                 glm::vec3 lightColour, float radius) {
    // The light's bounds (docs/scenes.md); a wall seen from inside a room is lit on the side the eye sees.
    setLightShading(light_, {.viewProjection = depth_.projection * f.view,
                             .origin = drawingOrigin(f.eye),
                             .eye = f.eye,
                             .light = light,
                             .lightColour = lightColour,
                             .ambient = ambient,
                             .radius = radius,
                             .twoSided = true});
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
      light_.set("model", models[i]);
      light_.set("colour", scene_.objects[i].colour);
      frontFaceFor(models[i]);
      gpu_[i]->draw();
    }
  }

  // A mirroring model matrix (a negative scale in a scene file) or a mirrored view turns every
  // winding round: front faces, for culling and for the two-sided stencil, are then clockwise.
  void frontFaceFor(const glm::mat4& model) const {
    const bool mirrored = (glm::determinant(glm::mat3(model)) < 0.0f) != mirroredView_;
    glFrontFace(mirrored ? GL_CW : GL_CCW);
  }

  Scene owned_;         // the built-in scene, when there is no file
  const Scene& scene_;  // the one drawn
  bool fromFile_;       // a file's lights all shine; the variants pick among the built-in scene's
  bool mirroredView_ = false;
  DepthMapping depth_;  // this frame's: its depth tests and the projection it draws with
  Program light_, volume_;
  std::vector<std::unique_ptr<GpuMesh>> gpu_;
  SolidsSeen solids_;  // this frame's rooms
  // A run of one object's volume vertices, counted together: the whole volume, or one piece of
  // a caster whose volume could nest deeper than a count group's 127.
  struct VolumePiece {
    std::size_t object;
    GLint first;
    GLsizei count;
    std::size_t nesting;  // the most this piece can add to a pixel's count
  };
  std::vector<std::vector<VolumePiece>> pieces_;        // per light
  std::vector<bool> convex_;                            // per object: a convex caster nests once
  std::vector<BoundingSphere> casterBounds_;            // per object, object space
  WindowRectangle window_;                              // the whole window, for folding the count
  std::vector<std::unique_ptr<GpuTriangles>> volumes_;  // per light, per object (empty for non-casters)
  std::vector<glm::mat4> volumeModels_;
  GpuLines silhouettes_;

  // ---- test hooks ---------------------------------------------------------------------------------

 public:
  // The light drawn last keeps its count in the stencil. Every visible object receives, the
  // casters included (their unlit sides lie in their own volumes). A count of zero is lit.
  std::optional<ShadowCheck> shadowCheck(const Frame& f) const override {
    if (!f.on("shadow")) return std::nullopt;
    ShadowCheck check{
        {}, lightsInOrder(f).back().light.position, [](std::uint8_t s) { return s == 0; }, true};
    const std::vector<glm::mat4> models = modelsAt(f.time);
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
      const SceneObject& o = scene_.objects[i];
      check.objects.push_back({&o.mesh, models[i], o.casts, o.receives});
    }
    return check;
  }
};

// The scene built in: a ground, a back wall and three closed casters, three lights.
Scene builtInScene() {
  Scene scene;
  scene.ambient = glm::vec3(0.22f);
  const auto add = [&scene](std::string name, Mesh mesh, glm::mat4 model, glm::vec3 colour, bool casts) {
    scene.objects.push_back(sceneObject(std::move(name), std::move(mesh), model, colour, casts));
    return &scene.objects.back();
  };
  const glm::mat4 wall =
      glm::rotate(glm::translate(glm::mat4(1), {0, 3, -4}), glm::radians(90.0f), {1, 0, 0});
  add("ground", makePlane(4.0f), glm::mat4(1), {0.75f, 0.75f, 0.7f}, false);
  add("wall", makePlane(4.0f), wall, {0.7f, 0.68f, 0.65f}, false);
  add("cube", makeCube(0.5f), glm::rotate(glm::translate(glm::mat4(1), {0, 1.7f, 0}), 0.6f, {1, 0, 1}),
      {0.9f, 0.45f, 0.2f}, true)
      ->spinDegPerSecond = 20.0f;
  add("ball", makeSphere(0.45f, 24, 12), glm::translate(glm::mat4(1), {1.5f, 1.0f, 0.9f}), {0.3f, 0.7f, 0.4f},
      true);
  SceneObject* torus = add("torus", makeTorus(0.55f, 0.18f, 32, 12),
                           glm::rotate(glm::translate(glm::mat4(1), {-1.5f, 1.1f, 0.7f}), 1.1f, {1, 0, 0}),
                           {0.85f, 0.4f, 0.5f}, true);
  torus->spinAxis = {0, 0, 1};
  torus->spinDegPerSecond = 25.0f;
  scene.lights = {{{1.6f, 5.5f, 1.8f, 1.0f}, {1.0f, 0.97f, 0.9f}},
                  {{-3.5f, 4.0f, 2.5f, 1.0f}, {0.95f, 0.3f, 0.25f}},
                  {{3.0f, 3.5f, -1.0f, 1.0f}, {0.3f, 0.45f, 1.0f}}};
  return scene;
}

// ---- the lesson: options, variants, cameras ------------------------------------------------------

// The lesson's view: the far plane at infinity (Pinf).
OrbitCamera pinfCamera() {
  return {.target = {0.0f, 0.9f, 0.0f},
          .distance = 10.0f,
          .azimuthDeg = 28.0f,
          .elevationDeg = 30.0f,
          .fovyDeg = 45.0f,
          .nearPlane = 0.1f,
          .farPlane = kInfinity};
}

// The same view with a far plane just beyond the scene: it cuts the volumes behind it.
OrbitCamera finiteFarCamera() {
  OrbitCamera c = pinfCamera();
  c.farPlane = 16.0f;
  return c;
}

// Looking down past the cube at its shadow, the near plane (1.0) far enough out to cut through
// the side of the cube's volume: the rays that start inside it miss their entry.
OrbitCamera nearPlaneCamera() {
  return {.target = {-0.72f, 0.0f, -0.8f},
          .distance = 2.2f,
          .azimuthDeg = 140.0f,
          .elevationDeg = 40.0f,
          .fovyDeg = 70.0f,
          .nearPlane = 1.0f,
          .farPlane = kInfinity};
}

// The eye between the cube and its shadow on the ground, inside the cube's volume.
OrbitCamera eyeInsideCamera() {
  return {.target = {1.5f, 0.3f, 2.5f},
          .distance = 3.9f,
          .azimuthDeg = -150.0f,
          .elevationDeg = 8.0f,
          .fovyDeg = 70.0f,
          .nearPlane = 0.1f,
          .farPlane = kInfinity};
}

// A parallel view: w = 0 has no place in it (see extrusionReach).
OrbitCamera orthographicCamera() {
  OrbitCamera c = pinfCamera();
  c.orthographic = true;
  c.azimuthDeg = 24.0f;
  c.orthoHeight = 9.0f;
  c.nearPlane = 0.1f;
  c.farPlane = 20.0f;
  return c;
}

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "15-robust-zfail";
  info.title = "Robust z-fail shadow volumes";
  info.summary =
      "Closed volumes counted behind the surface (z-fail) with two-sided wrapping stencil, the far plane\n"
      "at infinity or depth clamping, point and directional lights, coloured lights over an ambient pass.";
  info.options = {
      {"zpass", 'Z', "count in front of the surface (z-pass) instead of behind it (z-fail)", 0},
      {"caps", 'C', "close the volumes with their caps (off: the sides alone, all that z-pass needs)", 1},
      {"depth-clamp", 'D', "GL_DEPTH_CLAMP while counting: nothing beyond the far plane is clipped", 0},
      {"lights", 'N',
       "how many of the built-in scene's lights shine, the first ones (0: all; a file's all shine)", 0, 8},
      {"directional", 'L', "the first light becomes a directional light", 0},
      {"last", 'K', "the light drawn last, whose count the stencil keeps (--oracle checks it)", 0, 8},
      {"shadow", 'H', "shadows at all (off: every light everywhere)", 1},
      {"mark", 'U',
       "after counting, mark the casters' sides turned from the light shadowed (float depth path only;\n"
       "      off: the count alone)",
       1},
      {"show", 'X', "draw the volumes translucently and the silhouettes as lines", 0},
  };
  const std::vector<Feature> clamp = {Feature::DepthClamp};
  info.variants = {
      {"zfail", "z-fail, the far plane at infinity, two-sided wrapping stencil", {{"lights", 1}}},
      {"pinf-fixed24",
       "the same on the old path: a 24-bit fixed-point depth buffer with GL's depth mapping (Pinf)",
       {{"lights", 1}},
       {},
       {},
       false},
      {"zpass",
       "z-pass with the same view: where nothing clips, the very same counts",
       {{"lights", 1}, {"zpass", 1}}},
      {"zpass-near-plane",
       "z-pass with the near plane cutting the cube's volume: the entries it clips are lost",
       {{"lights", 1}, {"zpass", 1}, {"mark", 0}},
       {},
       nearPlaneCamera()},
      {"zfail-near-plane",
       "the same view with z-fail: nothing behind the surface is clipped",
       {{"lights", 1}},
       {},
       nearPlaneCamera()},
      {"zfail-no-caps",
       "z-fail counting the sides alone: an open volume's count is off",
       {{"lights", 1}, {"caps", 0}}},
      {"zfail-finite-far",
       "z-fail with a finite far plane: it clips the volumes' far ends, their exits are lost",
       {{"lights", 1}},
       {},
       finiteFarCamera()},
      {"depth-clamp",
       "the same finite far plane with depth clamping: the far ends are kept",
       {{"lights", 1}, {"depth-clamp", 1}},
       clamp,
       finiteFarCamera()},
      {"orthographic",
       "a parallel view: volumes pushed past the scene, depth-clamped",
       {{"lights", 1}, {"depth-clamp", 1}},
       clamp,
       orthographicCamera()},
      {"directional",
       "a directional light: the sides meet at one point at infinity",
       {{"lights", 1}, {"directional", 1}}},
      {"eye-inside",
       "the eye inside the cube's volume: z-fail needs no correction",
       {{"lights", 1}},
       {},
       eyeInsideCamera()},
      {"coloured-lights", "three coloured lights added over the ambient pass", {}},
      {"show-volumes", "the volumes translucently, the silhouettes as lines", {{"show", 1}}},
  };
  info.sceneLightOption = "last";
  info.shadows = true;
  info.passes = {"ambient", "volumes", "lit", "show-volumes", "silhouettes"};
  info.camera = pinfCamera();
  info.reversedDepth = true;  // a float depth buffer, reversed, where the driver has clip control
  return info;
}

}  // namespace

int main(int argc, char** argv) {
  return runSceneLesson(
      lessonInfo(), [](const Scene* fromFile) { return std::make_unique<RobustZFail>(fromFile); }, argc,
      argv);
}
