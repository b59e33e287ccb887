// Lesson 10 around its algorithms: the options, variants and camera a class chooses from, the
// scene (an area light over a slab, a ball and a mat on the ground), the targets the lights add
// into, the drawing the passes share, the snapshots, and the oracle's claim. None changes how a
// shadow is counted.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <stdexcept>
#include <string>

#include "geometry/shapes.h"
#include "gl/errors.h"
#include "gl/framebuffer.h"
#include "soft_shadows.h"

namespace stencil::soft_shadows {

// ---- the lesson: options, variants, camera -------------------------------------------------------

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "10-soft-shadows";
  info.title = "Soft shadows from light clusters";
  info.summary =
      "An area light sampled by N point lights, each with a hard shadow volume, each added at 1/N where\n"
      "its shadow is not: Kilgard's eight stencil bits, where they fail, and a count per light in float.";
  info.options = {
      {"method", 'M',
       "0 counting: per light a z-fail count in the whole stencil; 1 Kilgard: per light one stencil bit,\n"
       "      inverted by its volumes (z-pass parity), eight lights to a stencil clear",
       0, 1},
      {"lights", 'N', "the point lights sampling the area light", 16, kMaxLights, 1},
      {"pattern", 'T', "where the lights sit: 0 a grid, 1 jittered (one random point per cell), 2 Halton", 1,
       2},
      {"disk", 'D', "a disk light instead of the rectangle", 0},
      {"size", 'I', "the light's width in tenths of a unit (depth: two thirds of it); 0 a point", 15, 30},
      {"float", 'F',
       "the accumulation target: 1 RGBA32F, 2 RGBA16F (an 11-bit mantissa: N additions near 1 each round),\n"
       "      0 RGBA8 (each light's term rounded to 1/255)",
       1, 2},
      {"scale", 'W', "each light adds 1/N of the area light (off: the whole light each)", 1},
      {"update-bit", 'U', "adding a light sets the stencil bit it tested: one addition per pixel per light",
       1},
      {"depth-equal", 'E', "light only the ambient pass's surfaces (depth EQUAL; off: no depth test)", 1},
      {"blend", 'B', "add the lights (off: each replaces what is there)", 1},
      {"bit-mask", 'K', "Kilgard: a light's volumes write only its own bit (off: all eight bits)", 1},
      {"volume-colour", 'C', "the volumes also write colour (a state left on)", 0},
      {"volume-depth", 'Z', "the volumes also write depth (a state left on)", 0},
      {"reclear", 'J', "Kilgard past eight lights: clear the stencil before each group of eight", 1},
      {"casters", 'A', "1 the slab, 2 a ball, 3 both (their volumes overlap)", 1, 3, 1},
      {"mat", 'G', "a mat on the ground made of the ground's own triangles (equal depths)", 1},
      {"visibility", 'Y',
       "each light adds 1/N of white, unshaded, to the ground: the picture is the visible fraction", 0},
      {"reference", 'Q', "the exact visible fraction (analytic; the slab only) instead of the lights", 0},
      {"converged", '4',
       "with reference (Q): the reference ray cast instead, any casters: 2^converged stratified shadow\n"
       "      rays per pixel (geometry/soft_shadow_reference.h; 0: the analytic one)",
       0, 14},
      {"progressive", 'O', "each frame adds N new samples to a running average", 0},
      {"penumbra", 'X', "tint the penumbra: pixels some lights reach and some do not (float only)", 0},
      {"light", 'L', "the light whose hard shadow the final stencil holds (the one --oracle checks)", 0,
       kMaxLights - 1},
      {"shadow", 'H', "shadows at all (off: every light reaches everything)", 1},
      {"wedges", '1',
       "penumbra wedges (counting only): the N-light loop only in the wedges' pixels, one light's hard\n"
       "      shadow deciding everywhere else",
       0},
      {"show-wedges", '2', "tint the pixels the wedges mark (wedges only)", 0},
      {"wedge-size", '3',
       "the light the wedges are built from, in percent of the real one (test hook: under 100 the wedges\n"
       "      miss part of the penumbra)",
       100, 100},
  };
  info.variants = {
      {"counting",
       "sixteen jittered lights, each counted by z-fail in the whole stencil, float accumulation",
       {}},
      {"kilgard-8",
       "Kilgard's recipe: eight lights on a grid, a stencil bit each, 1/8 each",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}}},
      {"kilgard-no-update-bit",
       "the tested bit not set when the light is added: the mat adds each light twice",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}, {"update-bit", 0}}},
      {"kilgard-no-depth-equal",
       "no depth test when the lights are added: hidden ground lights the slab",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}, {"depth-equal", 0}}},
      {"kilgard-no-blend",
       "each light replaces the last: only the eighth remains",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}, {"blend", 0}}},
      {"kilgard-no-scale",
       "each light at full intensity: eight times too bright",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}, {"scale", 0}}},
      {"kilgard-no-bit-mask",
       "each light's volumes invert all eight bits: the shadows mix",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}, {"bit-mask", 0}}},
      {"kilgard-volume-colour",
       "colour writes left on while the volumes are drawn",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}, {"volume-colour", 1}}},
      {"kilgard-volume-depth",
       "depth writes left on while the volumes are drawn: EQUAL fails behind them",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}, {"volume-depth", 1}}},
      {"kilgard-overlap",
       "two casters whose volumes overlap: parity lights the overlap",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}, {"casters", 3}, {"light", 7}}},
      {"counting-overlap",
       "the same two casters counted: the overlap stays dark",
       {{"casters", 3}, {"light", 7}}},
      {"kilgard-16",
       "sixteen lights in two groups of eight, the stencil cleared between them",
       {{"method", 1}, {"lights", 16}, {"pattern", 0}}},
      {"kilgard-16-no-reclear",
       "sixteen lights without the clear: lights 8-15 find their bits set, add nothing",
       {{"method", 1}, {"lights", 16}, {"pattern", 0}, {"reclear", 0}, {"light", 8}}},
      {"kilgard-8-8bit",
       "Kilgard's eight lights added in an RGBA8 buffer: each 1/8 term rounded",
       {{"method", 1}, {"lights", 8}, {"pattern", 0}, {"float", 0}}},
      {"banding",
       "four lights on a grid: five levels, bands across the penumbra",
       {{"lights", 4}, {"pattern", 0}}},
      {"many-8bit",
       "256 lights in RGBA8: the terms below one level vanish",
       {{"lights", 256}, {"float", 0}, {"pattern", 2}}},
      {"many", "256 Halton lights in RGBA32F", {{"lights", 256}, {"pattern", 2}}},
      {"many-16f",
       "256 Halton lights in RGBA16F: rounding near 1 adds up over the lights",
       {{"lights", 256}, {"pattern", 2}, {"float", 2}}},
      {"disk", "a disk light, 64 Halton lights", {{"lights", 64}, {"pattern", 2}, {"disk", 1}}},
      {"visibility",
       "64 Halton lights, the visible fraction unshaded",
       {{"lights", 64}, {"pattern", 2}, {"visibility", 1}}},
      {"reference", "the exact visible fraction, analytic", {{"reference", 1}, {"visibility", 1}}},
      {"converged",
       "the visible fraction past the slab and the ball, ray cast with 1024 shadow rays per pixel",
       {{"reference", 1}, {"visibility", 1}, {"converged", 10}, {"casters", 3}}},
      {"penumbra", "the penumbra tinted", {{"penumbra", 1}}},
      {"wedges",
       "sixteen jittered lights, the N-light loop only inside the penumbra wedges",
       {{"wedges", 1}}},
      {"wedges-marked",
       "the pixels the penumbra wedges mark, tinted: the only ones where N lights run",
       {{"wedges", 1}, {"show-wedges", 1}, {"casters", 3}}},
  };
  info.shadows = true;
  // Snapshots after the first light's (or first eight's) volumes and illumination, then after all
  // the others: a pass per light would copy the frame once per light.
  info.passes = {"ambient", "wedges", "volumes", "illumination", "other-lights", "resolve"};
  info.camera.target = {0.2f, 0.3f, 0.3f};
  info.camera.distance = 6.6f;
  info.camera.azimuthDeg = 20.0f;
  info.camera.elevationDeg = 52.0f;
  info.camera.farPlane = kInfinity;  // z-fail's dark caps at infinity stay in the frustum
  info.refuseOptions = [](const OptionsChosen& o) -> std::string {
    if (o.set("light") && o.value("light") >= o.value("lights"))
      return "--set light=" + std::to_string(o.value("light")) + ": there are " +
             std::to_string(o.value("lights")) + " lights (0 to " + std::to_string(o.value("lights") - 1) + ")";
    return {};
  };
  return info;
}

// ---- the scene ------------------------------------------------------------------------------------

AreaLight areaLight(const Frame& f) {
  const float width = 0.1f * static_cast<float>(f.option("size"));
  return {{0.0f, kLightHeight, 0.0f},
          {width, width * 2.0f / 3.0f},
          f.on("disk") ? LightShape::Disk : LightShape::Rectangle};
}

glm::mat4 slabModel() {
  return glm::scale(glm::translate(glm::mat4(1.0f), kSlabCentre), {kSlabSide, kSlabThickness, kSlabSide});
}

// The ground's triangles whose centre lies in the mat's square, the same vertices: the mat's
// depths are the ground's to the last bit, so depth EQUAL passes both.
Mesh matFrom(const Mesh& ground) {
  Mesh mat;
  for (std::size_t t = 0; t + 2 < ground.indices.size(); t += 3) {
    glm::vec3 c(0.0f);
    for (int k = 0; k < 3; ++k) c += ground.positions[ground.indices[t + static_cast<std::size_t>(k)]];
    c /= 3.0f;
    if (c.x < 0.5f || c.x > 2.0f || c.z < -1.0f || c.z > 1.0f) continue;  // whole cells of 0.5
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = ground.indices[t + static_cast<std::size_t>(k)];
      mat.indices.push_back(static_cast<std::uint32_t>(mat.positions.size()));
      mat.positions.push_back(ground.positions[i]);
      mat.normals.push_back(ground.normals[i]);
    }
  }
  return mat;
}

// The scene, built once (it stands still): the ground, the mat, the slab and the ball, on the GPU,
// and the two casters welded in world space for their volumes.
SoftShadows::SoftShadows()
    : light_("common/light.vert", "common/light.frag"),
      flat_("common/flat.vert", "common/flat.frag"),
      volume_("common/volume.vert", "common/flat.frag"),
      resolve_("common/volume.vert", "10-soft-shadows/resolve.frag"),
      lights_("common/light.vert", "10-soft-shadows/lights.frag"),
      groundMesh_(makePlane(kGroundHalf, kGroundDivisions)),
      matMesh_(matFrom(groundMesh_)),
      slabMesh_(makeCube(0.5f)),
      ballMesh_(makeSphere(kBallRadius, 24, 12)),
      ground_(groundMesh_),
      mat_(matMesh_),
      slab_(slabMesh_),
      ball_(ballMesh_),
      slabEdges_(prepareCaster(transformed(slabMesh_, slabModel()))),
      ballEdges_(prepareCaster(transformed(ballMesh_, glm::translate(glm::mat4(1.0f), kBallCentre)))) {
  glGenTextures(1, &lightsTexture_);
}

SoftShadows::~SoftShadows() {
  glDeleteTextures(1, &lightsTexture_);
}

// Combinations the lesson cannot draw, refused before anything is drawn.
void SoftShadows::checkOptions(const Frame& f) {
  const bool kilgard = f.option("method") == 1;
  if (f.on("reference") && f.option("size") == 0)
    throw UsageError("--set reference=1 needs a light of size 1 or more");
  if (f.on("reference") && !f.on("converged") && f.option("casters") != 1)
    throw UsageError("--set reference=1 needs casters=1 (the slab alone) unless converged is on");
  if (f.on("wedges") && (kilgard || f.on("reference")))
    throw UsageError("--set wedges=1 needs method=0 (counting) and reference=0");
}

// The counts --stats reports in every frame, 0 where the frame's method does not touch them.
void SoftShadows::startCounts(Frame& f) {
  for (const char* name :
       {"lights", "rounds", "samples", "stencil_clears", "volume_triangles", "illumination_draws",
        "light_groups", "penumbra_width_x_milli", "penumbra_width_x_predicted_milli",
        "penumbra_width_z_milli", "penumbra_width_z_predicted_milli", "wedges", "wedge_triangles",
        "reference_rays_per_pixel"})
    f.count(name, 0);
}

// What the options put in the scene: the ground, the mat, and the casters chosen.
std::vector<Object> SoftShadows::sceneOf(const Frame& f) const {
  std::vector<Object> scene;
  scene.push_back({&groundMesh_, &ground_, glm::mat4(1.0f), {0.75f, 0.74f, 0.7f}, false});
  if (f.on("mat")) scene.push_back({&matMesh_, &mat_, glm::mat4(1.0f), {0.75f, 0.4f, 0.3f}, false});
  if (f.option("casters") & 1)
    scene.push_back({&slabMesh_, &slab_, slabModel(), {0.35f, 0.55f, 0.85f}, true});
  if (f.option("casters") & 2)
    scene.push_back(
        {&ballMesh_, &ball_, glm::translate(glm::mat4(1.0f), kBallCentre), {0.4f, 0.75f, 0.4f}, true});
  return scene;
}

std::vector<const PreparedCaster*> SoftShadows::casters(const Frame& f) const {
  std::vector<const PreparedCaster*> c;
  if (f.option("casters") & 1) c.push_back(&slabEdges_);
  if (f.option("casters") & 2) c.push_back(&ballEdges_);
  return c;
}

// The light's share: 1/N of it, or all of it without the scale.
float SoftShadows::share(const Frame& f) {
  return f.on("scale") ? 1.0f / static_cast<float>(f.option("lights")) : 1.0f;
}

// ---- the drawing the passes share ----------------------------------------------------------------

// visibility: receivers only, unshaded, 1/N of white each (the fraction of the light seen).
// allLights: every light of samples_ summed in one draw, each at `colour`; in visibility, the N
// shares added in the lights' order, as N blended draws would add them.
void SoftShadows::drawScene(const Frame& f, const std::vector<Object>& scene, glm::vec4 light,
                            glm::vec3 colour, glm::vec3 ambient, bool visibility, bool allLights) {
  glEnable(GL_CULL_FACE);  // closed casters and the ground seen from above
  if (visibility) {
    const float s = share(f);
    glm::vec4 c(s, s, s, 1.0f);
    if (allLights) {
      float sum = 0.0f;
      for (std::size_t i = 0; i < samples_.size(); ++i) sum += s;
      c = glm::vec4(sum, sum, sum, static_cast<float>(samples_.size()));
    }
    flat_.set("colour", c);
    for (std::size_t k = scene.size(); k-- > 0;) {  // the mat before the ground, as below
      const Object& o = scene[k];
      if (o.caster) continue;  // the ground and the mat: the reference's receivers
      flat_.set("transform", f.projection * f.view * o.model);
      o.gpu->draw();
    }
    glDisable(GL_CULL_FACE);
    return;
  }
  const Program& program = allLights ? lights_ : light_;
  program.set("viewProjection", f.projection * f.view);
  program.set("lightColour", colour);
  program.set("eye", f.eye);
  program.set("shininess", 24.0f);
  if (allLights) {
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, lightsTexture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, static_cast<GLsizei>(samples_.size()), 1, 0, GL_RGBA, GL_FLOAT,
                 samples_.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glActiveTexture(GL_TEXTURE0);
    program.set("lights", 1);
    program.set("count", static_cast<int>(samples_.size()));
  } else {
    light_.set("ambient", ambient);
    light_.set("light", light);
  }
  // Adding light, the mat goes before the ground it lies on: the surface the ambient pass left
  // on top is the one that takes the light (the other then fails the updated bit).
  const bool adding = colour != glm::vec3(0.0f);
  for (std::size_t k = 0; k < scene.size(); ++k) {
    const Object& o = scene[adding && k < 2 && scene.size() > 1 && !scene[1].caster ? 1 - k : k];
    program.set("model", o.model);
    program.set("colour", o.colour);
    o.gpu->draw();
  }
  glDisable(GL_CULL_FACE);
}

// One shadow volume (Kilgard's, triangles) drawn with the state the caller set.
void SoftShadows::drawVolume(Frame& f, const ShadowVolume& v) {
  volumeStream_.upload(v.vertices);
  volumeStream_.draw();
  f.count("volume_triangles", v.triangleCount());
}

// ---- the targets, the snapshots, the picture ------------------------------------------------------

Target::Target(glm::ivec2 size, GLenum colourFormat, bool depthStencil) : size_(size), format_(colourFormat) {
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glGenTextures(1, &colour_);
  glBindTexture(GL_TEXTURE_2D, colour_);
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(colourFormat), size.x, size.y, 0, GL_RGBA, GL_FLOAT,
               nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_, 0);
  if (depthStencil) {
    glGenRenderbuffers(1, &depthStencil_);
    glBindRenderbuffer(GL_RENDERBUFFER, depthStencil_);
    glRenderbufferStorage(GL_RENDERBUFFER, depthStencilFormat(DepthFormat::Fixed24), size.x, size.y);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depthStencil_);
  }
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("lesson 10's accumulation framebuffer is incomplete");
}

Target::~Target() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteTextures(1, &colour_);
  if (depthStencil_) glDeleteRenderbuffers(1, &depthStencil_);
}

void Target::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, size_.x, size_.y);
}

// Copies what `mask` names from one framebuffer to another of the same size.
void blit(GLuint from, GLuint to, glm::ivec2 size, GLbitfield mask) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, from);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to);
  glBlitFramebuffer(0, 0, size.x, size.y, 0, 0, size.x, size.y, mask, GL_NEAREST);
}

// A named pass's snapshot: the target copied into the framework's framebuffer, where it is read.
void SoftShadows::endPass(Frame& f, const char* name) {
  blit(target_->fbo(), framework_, f.size, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  f.pass(name);
  target_->bind();  // the blit left the framework's framebuffer bound
}

// The checked light's stencil, kept for the end of the frame (and the oracle).
void SoftShadows::saveStencil() {
  blit(target_->fbo(), saved_->fbo(), size_, GL_STENCIL_BUFFER_BIT);
  target_->bind();
}

// A texture onto the bound framebuffer, one texel per pixel.
void SoftShadows::drawPicture(const Target& from, int lights, bool tint) {
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, from.colour());
  resolve_.set("transform", glm::mat4(1.0f));
  resolve_.set("picture", 0);
  resolve_.set("lights", static_cast<float>(lights));
  resolve_.set("tint", tint ? 1 : 0);
  window_.draw();
  glEnable(GL_DEPTH_TEST);
}

// The pixels the wedges marked (their bit, kept in the saved stencil) tinted, over the picture in
// the framework's framebuffer, which is bound. Writes colour only.
void SoftShadows::tintWedges() {
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, kWedgeBit, kWedgeBit);
  glStencilMask(0);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  volume_.set("transform", glm::mat4(1.0f));
  volume_.set("colour", glm::vec4(0.1f, 0.85f, 0.95f, 0.5f));
  window_.draw();
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glStencilMask(0xFF);
  glEnable(GL_DEPTH_TEST);
}

// ---- the oracle's claim -------------------------------------------------------------------------

std::optional<ShadowCheck> SoftShadows::shadowCheck(const Frame& f) const {
  if (!f.on("shadow") || f.on("reference") || samples_.empty()) return std::nullopt;
  const bool kilgard = f.option("method") == 1;
  const std::uint8_t bit = static_cast<std::uint8_t>(1u << (checked_ % 8));
  // With the wedges the saved stencil also holds the wedges' bit; the count is in the low bits.
  const auto countMask = static_cast<std::uint8_t>(f.on("wedges") ? kCountBits : 0xFFu);
  ShadowCheck check{
      {},
      samples_[static_cast<std::size_t>(checked_)],
      [kilgard, bit, countMask](std::uint8_t s) { return kilgard ? (s & bit) == 0 : (s & countMask) == 0; },
      true};
  for (const Object& o : sceneOf(f)) check.objects.push_back({o.mesh, o.model, o.caster, true});
  return check;
}

}  // namespace stencil::soft_shadows
