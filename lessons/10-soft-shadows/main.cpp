// Lesson 10: soft shadows from a cluster of point lights (Kilgard, "Improving Shadows and
// Reflections via the Stencil Buffer", section 6.4 and figure 15, after Brotman and Badler 1984).
//
// An area light casts a penumbra: a receiver point there sees part of the light. Sample the light
// with N point lights, give each a hard shadow volume, and add each light at 1/N intensity where
// it is not shadowed: a point that k of the N lights reach gets k/N of the light, an estimate of
// the fraction of the area light it sees.
//
// Kilgard's recipe (the variant kilgard-8), eight lights, one stencil bit each:
//   1. the scene with ambient light only, filling the depth buffer;
//   2. per light i, its shadow volumes with stencil write mask 1 << i, INVERT where the depth
//      test passes (z-pass parity, lesson 07), colour and depth writes off;
//   3. per light i, the scene again at 1/8 of the light, added (blend ONE, ONE), only on the
//      ambient pass's surfaces (depth EQUAL), where bit i is 0 -- and bit i set where the light
//      is added, so a second surface at the same depth (a coplanar mat here) cannot add it again.
// Its limits, each a variant: N lights give N + 1 levels (banding); INVERT is parity, so the
// overlap of two casters' volumes is lit; eight bits hold eight lights, so more need a stencil
// clear per eight; an 8-bit colour buffer rounds each 1/N term.
//
// The default corrects them: per light a robust z-fail count (closed volumes, lesson 15) in the
// whole stencil, the light added where the count is 0, into a float target; any N.
//
// Penumbra wedges (the variant wedges; Assarsson and Akenine-Moller 2003): only the penumbra needs
// N lights. Around every edge that is a silhouette edge from some point of the light, a convex
// wedge (the edge and its extrusions away from the light's corners) bounds the region where the
// lights can disagree; the wedges mark their pixels in a stencil bit, the N-light loop runs only
// there, and outside one light's hard shadow decides, every light added at once where it is lit.
//
// In this file, in that order: the frame (render: the light sampled, step 1, the lights, the
// picture resolved), Kilgard's steps 2 and 3 (kilgardLights, illuminate), the corrected count
// (countingLights, countVolumes), the penumbra wedges (wedgeLights, penumbraWedges). Beside it:
// soft_shadows.h (the scene's measures, the stencil bits, the lesson's declaration),
// reference.cpp (the exact visible fraction, the converged ray cast, the penumbra's width),
// classroom.cpp (options, variants, camera, the scene, the targets, the drawing the passes share,
// the oracle's claim) and convex_hull.cpp (the wedges' hulls). The light's samples and the exact
// fraction are in geometry/soft_shadow.h, the volumes in geometry/shadow_volume.h.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "soft_shadows.h"

namespace stencil::soft_shadows {

// ---- the frame: the light sampled, the ambient pass, each light, the picture ------------------

void SoftShadows::render(Frame& f) {
  checkOptions(f);  // a combination the lesson cannot draw: one line, exit 2
  startCounts(f);
  const int n = f.option("lights");
  const bool kilgard = f.option("method") == 1;
  framework_ = f.framebuffer();
  size_ = f.size;
  const GLenum format = f.option("float") == 1 ? GL_RGBA32F : f.option("float") == 2 ? GL_RGBA16F : GL_RGBA8;
  if (!target_ || !target_->fits(f.size, format)) target_ = std::make_unique<Target>(f.size, format, true);
  if (!saved_ || !saved_->fits(f.size, GL_RGBA8)) saved_ = std::make_unique<Target>(f.size, GL_RGBA8, true);

  // The light sampled: N point lights over it. Progressive refinement: the same options as the
  // last frame make another round of samples.
  std::string key = std::to_string(f.size.x) + "x" + std::to_string(f.size.y);
  for (const Option& o : lessonInfo().options) key += "," + std::to_string(f.option(o.name));
  round_ = (f.on("progressive") && key == lastKey_) ? round_ + 1 : 0;
  lastKey_ = key;
  const AreaLight area = areaLight(f);
  samples_.clear();
  for (glm::vec2 u : unitSquareSamples(static_cast<SamplePattern>(f.option("pattern")), n, round_))
    samples_.push_back(glm::vec4(lightPoint(area, u), 1.0f));
  f.count("lights", static_cast<std::uint64_t>(n));
  f.count("rounds", static_cast<std::uint64_t>(round_ + 1));
  f.count("samples", static_cast<std::uint64_t>(n) * static_cast<std::uint64_t>(round_ + 1));
  checked_ = std::min(f.option("light"), n - 1);

  target_->bind();
  const std::vector<Object> scene = sceneOf(f);
  const glm::mat4 viewProjection = f.projection * f.view;

  // ---- 1. ambient: the depth buffer filled once, for every light ---------------------------
  glClearColor(0.02f, 0.025f, 0.035f, 0.0f);
  glClearStencil(0);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);                            // the mat, drawn after the ground at equal depths, shows
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);  // alpha counts lights, from 0
  const bool visibility = f.on("visibility") || f.on("reference");
  drawScene(f, scene, glm::vec4(0, 1, 0, 0), glm::vec3(0.0f), visibility ? glm::vec3(0.0f) : kAmbient, false);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  endPass(f, "ambient");

  if (f.on("reference") && f.on("converged")) {
    drawConverged(f, scene, area, viewProjection);
  } else if (f.on("reference")) {
    drawReference(f, area, viewProjection);
  } else if (kilgard) {
    kilgardLights(f, scene);
  } else if (f.on("wedges")) {
    wedgeLights(f, scene, area);
  } else {
    countingLights(f, scene);
  }

  // ---- the frame's light onto the framework's picture ------------------------------------------
  const Target* picture = target_.get();
  if (f.on("progressive")) {  // the running average of every round: weight 1 / rounds for this one
    if (!average_ || !average_->fits(f.size, GL_RGBA32F))
      average_ = std::make_unique<Target>(f.size, GL_RGBA32F, false);
    average_->bind();
    glEnable(GL_BLEND);
    glBlendColor(0.0f, 0.0f, 0.0f, 1.0f / static_cast<float>(round_ + 1));
    glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
    drawPicture(*target_, n, false);
    glDisable(GL_BLEND);
    picture = average_.get();
  }
  measurePenumbra(f, *picture, area);
  glBindFramebuffer(GL_FRAMEBUFFER, framework_);
  glViewport(0, 0, f.size.x, f.size.y);
  drawPicture(*picture, n, f.on("penumbra"));
  // The stencil the frame ends with: the checked light's hard shadow (saved after its volumes).
  blit(saved_->fbo(), framework_, f.size, GL_STENCIL_BUFFER_BIT);
  glBindFramebuffer(GL_FRAMEBUFFER, framework_);
  if (f.on("wedges") && f.on("show-wedges")) tintWedges();  // the wedges' bit, kept in the saved stencil
  f.pass("resolve");
}

// ---- Kilgard: a stencil bit per light ----------------------------------------------------------

// Steps 2 and 3 for every group of eight lights (one, for eight or fewer).
void SoftShadows::kilgardLights(Frame& f, const std::vector<Object>& scene) {
  const int n = f.option("lights");
  for (int group = 0; group * 8 < n; ++group) {
    const int first = group * 8, last = std::min(n, first + 8);
    f.count("light_groups");
    if (group == 0 || f.on("reclear")) {  // eight fresh bits
      glStencilMask(0xFF);
      glClear(GL_STENCIL_BUFFER_BIT);
      f.count("stencil_clears");
    }
    // 2. Each light's volumes invert its own bit wherever they lie in front of the scene.
    if (f.on("shadow")) {
      volumeState(f);
      glDepthFunc(GL_LESS);
      glStencilFunc(GL_ALWAYS, 0, 0xFF);
      glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);  // depth pass: one more crossing, parity flips
      for (int i = first; i < last; ++i) {
        glStencilMask(f.on("bit-mask") ? 1u << (i % 8) : 0xFFu);  // light i's bit alone
        for (const PreparedCaster* c : casters(f))
          drawVolume(f, silhouetteVolume(*c, samples_[static_cast<std::size_t>(i)], kInfinity));
      }
      restoreState();
    }
    if (checked_ >= first && checked_ < last) saveStencil();
    if (group == 0) endPass(f, "volumes");
    // 3. Each light added at 1/N where its bit is 0, setting the bit as it adds.
    for (int i = first; i < last; ++i) {
      const GLuint bit = 1u << (i % 8);
      glEnable(GL_STENCIL_TEST);
      glStencilFunc(GL_EQUAL, 0, bit);  // light i's bit clear: outside its volumes
      glStencilMask(bit);
      glStencilOp(GL_KEEP, GL_KEEP, f.on("update-bit") ? GL_INVERT : GL_KEEP);  // 0 -> 1: added once
      illuminate(f, scene, samples_[static_cast<std::size_t>(i)]);
    }
    if (group == 0) endPass(f, "illumination");
  }
  if (n > 8) endPass(f, "other-lights");
  glStencilMask(0xFF);
}

// Volumes touch only the stencil: no colour, no depth, both faces (unless a variant leaves a
// state on, to show why it is off).
void SoftShadows::volumeState(const Frame& f) {
  const GLboolean colour = f.on("volume-colour") ? GL_TRUE : GL_FALSE;
  glColorMask(colour, colour, colour, GL_FALSE);
  glDepthMask(f.on("volume-depth") ? GL_TRUE : GL_FALSE);
  glDisable(GL_CULL_FACE);
  glEnable(GL_STENCIL_TEST);
  volume_.set("transform", f.projection * f.view);
  volume_.set("colour", glm::vec4(1.0f, 0.85f, 0.2f, 1.0f));
}

void SoftShadows::restoreState() {
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
}

// Step 3 for one light (the counting system and the wedges add theirs the same way): the light
// added onto the ambient pass's surfaces where the stencil test (set by the caller) passes.
// allLights: every light of the round in one draw (outside the wedges), light unused.
void SoftShadows::illuminate(Frame& f, const std::vector<Object>& scene, const glm::vec4& light,
                             bool allLights) {
  glDepthMask(GL_FALSE);  // the surfaces stay
  if (f.on("depth-equal")) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_EQUAL);  // exactly the ambient pass's surfaces
  } else {
    glDisable(GL_DEPTH_TEST);
  }
  if (f.on("blend")) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);  // light adds up; alpha counts the lights that reached
  }
  drawScene(f, scene, light, kLightColour * share(f), glm::vec3(0.0f), f.on("visibility"), allLights);
  f.count("illumination_draws");
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
}

// ---- the corrected system: a z-fail count per light -----------------------------------------

// Per light: the stencil cleared, its closed volumes counted, the light added where the count is 0.
void SoftShadows::countingLights(Frame& f, const std::vector<Object>& scene) {
  const int n = f.option("lights");
  for (int i = 0; i < n; ++i) {
    const glm::vec4 light = samples_[static_cast<std::size_t>(i)];
    glStencilMask(0xFF);
    glClear(GL_STENCIL_BUFFER_BIT);  // this light's count starts at 0
    f.count("stencil_clears");
    countVolumes(f, light, false);
    if (i == checked_) saveStencil();
    if (i == 0) endPass(f, "volumes");
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 0, 0xFF);  // a count of 0: outside every volume
    glStencilMask(0x80);               // counts stay below 128 (two convex casters)
    glStencilOp(GL_KEEP, GL_KEEP, f.on("update-bit") ? GL_INVERT : GL_KEEP);  // 0 -> 128: added once
    illuminate(f, scene, light);
    if (i == 0) endPass(f, "illumination");
  }
  if (n > 1) endPass(f, "other-lights");
  glStencilMask(0xFF);
}

// One light's closed volumes counted by z-fail into the stencil: in the whole stencil, or with
// the wedges (inWedges) into kCountBits only, and only on pixels whose kWedgeBit is set.
void SoftShadows::countVolumes(Frame& f, const glm::vec4& light, bool inWedges) {
  if (f.on("shadow")) {
    volumeState(f);
    glDepthFunc(GL_LESS);  // behind the scene: fail
    if (inWedges) {
      glStencilFunc(GL_EQUAL, kWedgeBit, kWedgeBit);
      glStencilMask(kCountBits);  // INCR and DECR wrap modulo 16 there
    } else {
      glStencilFunc(GL_ALWAYS, 0, 0xFF);
      glStencilMask(f.on("wedges") ? kCountBits : 0xFFu);
    }
    glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);   // behind: the ray leaves a volume
    glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);  // behind: it enters one
    for (const PreparedCaster* c : casters(f)) {
      const ClosedVolume v = closedVolume(c->mesh, c->adjacency, light, kInfinity);
      const std::size_t sides = 3 * v.sideTriangles, lightCap = 3 * v.lightCapTriangles;
      volumeStream_.upload(v.triangles.vertices);
      volume_.set("transform", f.projection * f.view);
      volume_.set("colour", glm::vec4(1.0f, 0.85f, 0.2f, 1.0f));
      volumeStream_.draw(0, static_cast<GLsizei>(sides));  // the sides
      // The dark cap at infinity fails LESS by itself.
      volumeStream_.draw(static_cast<GLint>(sides + lightCap), static_cast<GLsizei>(3 * v.darkCapTriangles));
      glDepthFunc(GL_NEVER);  // the light cap lies on the caster's surface: never in front of it
      volumeStream_.draw(static_cast<GLint>(sides), static_cast<GLsizei>(lightCap));
      glDepthFunc(GL_LESS);
      f.count("volume_triangles", v.triangles.triangleCount());
    }
    restoreState();
  }
}

// ---- penumbra wedges (Assarsson and Akenine-Moller, "A Geometry-Based Soft Shadow Volume
// Algorithm Using Graphics Hardware", SIGGRAPH 2003): N lights only where they can disagree ----

// 1. The wedges marked, 2. one light deciding outside them, 3. the N-light loop inside them.
void SoftShadows::wedgeLights(Frame& f, const std::vector<Object>& scene, const AreaLight& area) {
  const int n = f.option("lights");
  glStencilMask(0xFF);
  glClear(GL_STENCIL_BUFFER_BIT);
  f.count("stencil_clears");
  // 1. The wedges into kWedgeBit, one at a time: z-fail parity in kTempBit is 1 exactly on the
  //    surfaces inside a convex wedge; the wedge's faces then copy it into kWedgeBit and clear it.
  if (f.on("shadow")) {
    std::vector<glm::vec4> wedges;
    std::vector<std::pair<GLint, GLsizei>> ranges;
    const float scale = 1.02f * static_cast<float>(f.option("wedge-size")) / 100.0f;  // 2% to spare
    for (const PreparedCaster* c : casters(f)) penumbraWedges(*c, area, scale, wedges, ranges);
    volumeState(f);
    volumeStream_.upload(wedges);
    for (const auto& [first, count] : ranges) {
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_LESS);
      glStencilFunc(GL_ALWAYS, 0, 0xFF);
      glStencilMask(kTempBit);
      glStencilOp(GL_KEEP, GL_INVERT, GL_KEEP);  // a face behind the surface: one crossing
      volumeStream_.draw(first, count);
      glDisable(GL_DEPTH_TEST);
      glStencilFunc(GL_EQUAL, kTempBit | kWedgeBit, kTempBit);  // inside: mark
      glStencilMask(kWedgeBit);
      glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
      volumeStream_.draw(first, count);
      glStencilFunc(GL_EQUAL, kTempBit, kTempBit);  // only where it is set: the rest fails early
      glStencilMask(kTempBit);
      glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);  // kTempBit back to 0 for the next wedge
      volumeStream_.draw(first, count);
    }
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    f.count("wedges", ranges.size());
    f.count("wedge_triangles", wedges.size() / 3);
    // A caster's own faces are shadowed by its volumes wherever they face away from the light
    // (not only behind an edge): its pixels are marked too, through the ambient pass's depths.
    glStencilFunc(GL_ALWAYS, kWedgeBit, 0xFF);
    glStencilMask(kWedgeBit);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glDepthFunc(GL_EQUAL);
    std::vector<Object> casterObjects;
    for (const Object& o : scene)
      if (o.caster) casterObjects.push_back(o);
    drawScene(f, casterObjects, glm::vec4(0, 1, 0, 0), glm::vec3(0.0f), glm::vec3(0.0f), false);
    glDepthFunc(GL_LESS);
    glDisable(GL_STENCIL_TEST);
    restoreState();
  }
  endPass(f, "wedges");
  // 2. One light decides outside the wedges (all agree there): the checked light's count
  //    everywhere, and every light added at once where it is 0.
  countVolumes(f, samples_[static_cast<std::size_t>(checked_)], false);
  saveStencil();
  endPass(f, "volumes");
  const GLuint tested = kWedgeBit | kCountBits | kAddedBit;
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 0, tested);  // outside the wedges, lit
  glStencilMask(kAddedBit);
  glStencilOp(GL_KEEP, GL_KEEP, f.on("update-bit") ? GL_INVERT : GL_KEEP);
  illuminate(f, scene, glm::vec4(0.0f), true);
  // 3. Inside the wedges, the plain loop: each light's count, each light added where it is 0.
  for (int i = 0; i < n; ++i) {
    const glm::vec4 light = samples_[static_cast<std::size_t>(i)];
    glStencilMask(kCountBits | kAddedBit);
    glClear(GL_STENCIL_BUFFER_BIT);  // the wedges' bit stays
    f.count("stencil_clears");
    countVolumes(f, light, true);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, kWedgeBit, tested);  // in a wedge, lit by light i
    glStencilMask(kAddedBit);
    glStencilOp(GL_KEEP, GL_KEEP, f.on("update-bit") ? GL_INVERT : GL_KEEP);
    illuminate(f, scene, light);
    if (i == 0) endPass(f, "illumination");
  }
  if (n > 1) endPass(f, "other-lights");
  glStencilMask(0xFF);
}

// Every wedge of a caster (welded, world space): for each edge that may be a silhouette edge from
// some point of the light's bounding rectangle, grown by `scale` (its two faces neither both
// front-facing nor both back-facing from all four corners; a border edge always), the convex hull
// of the edge and its endpoints extruded away from each corner down to y = kWedgeFloor. Every
// shadow-volume side of the edge from a light point inside the rectangle lies in that hull (its
// points are convex combinations of the corners' sides), so a receiver whose lights disagree lies
// in some wedge. Appends the triangles (w = 1) and each wedge's (first vertex, vertex count).
// Throws std::logic_error for an edge at or above the light (the lesson's scene has none).
void penumbraWedges(const PreparedCaster& caster, const AreaLight& area, float scale,
                    std::vector<glm::vec4>& out, std::vector<std::pair<GLint, GLsizei>>& ranges) {
  const glm::dvec2 half = 0.5 * static_cast<double>(scale) *
                          glm::dvec2(area.shape == LightShape::Disk ? glm::vec2(area.size.x) : area.size);
  const glm::dvec3 centre(area.centre);
  const std::array<glm::dvec3, 4> corners{
      centre + glm::dvec3(-half.x, 0.0, -half.y), centre + glm::dvec3(half.x, 0.0, -half.y),
      centre + glm::dvec3(half.x, 0.0, half.y), centre + glm::dvec3(-half.x, 0.0, half.y)};
  const std::vector<glm::vec3>& position = caster.mesh.positions;
  const std::vector<std::uint32_t>& index = caster.mesh.indices;
  auto faces = [&](std::int32_t face, const glm::dvec3& light) {
    const glm::dvec3 a(position[index[3 * static_cast<std::size_t>(face)]]);
    const glm::dvec3 b(position[index[3 * static_cast<std::size_t>(face) + 1]]);
    const glm::dvec3 c(position[index[3 * static_cast<std::size_t>(face) + 2]]);
    return glm::dot(glm::cross(b - a, c - a), light - a) > 0.0;
  };
  for (const Edge& e : caster.adjacency.edges) {
    if (e.face0 >= 0 && e.face1 >= 0) {
      bool allFront = true, allBack = true;
      for (const glm::dvec3& c : corners) {
        const bool f0 = faces(e.face0, c), f1 = faces(e.face1, c);
        allFront = allFront && f0 && f1;
        allBack = allBack && !f0 && !f1;
      }
      if (allFront || allBack) continue;  // never a silhouette edge
    }
    std::vector<glm::dvec3> points{glm::dvec3(position[e.v0]), glm::dvec3(position[e.v1])};
    for (const glm::dvec3& c : corners)
      for (std::size_t k = 0; k < 2; ++k) {
        const glm::dvec3 q = points[k];
        if (c.y - q.y < 1e-3) throw std::logic_error("a penumbra wedge's edge at or above the light");
        points.push_back(q + (q.y - kWedgeFloor) / (c.y - q.y) * (q - c));
      }
    const std::vector<glm::vec4> hull = convexHullTriangles(points);
    if (hull.empty()) continue;
    ranges.push_back({static_cast<GLint>(out.size()), static_cast<GLsizei>(hull.size())});
    out.insert(out.end(), hull.begin(), hull.end());
  }
}

}  // namespace stencil::soft_shadows

int main(int argc, char** argv) {
  using namespace stencil::soft_shadows;
  return stencil::runLesson(
      lessonInfo(), [] { return std::make_unique<SoftShadows>(); }, argc, argv);
}
