// Lesson 14's work buffer and draws: the scene's meshes on the GPU, the target faces of a product,
// the full-screen quads that push pixels to the far plane.
#include <algorithm>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>
#include <tuple>

#include "csg_lesson.h"
#include "geometry/shapes.h"
#include "gl/errors.h"

namespace stencil::csg_lesson {

Csg::Csg(const Scene* fromFile)
    : fromFile_(fromFile),
      light_("common/light.vert", "common/light.frag"),
      depthOnly_("common/light.vert", "14-csg/flat.frag"),
      merge_("14-csg/merge.vert", "14-csg/merge.frag"),
      select_("14-csg/merge.vert", "14-csg/select.frag"),
      keep_("common/flat.vert", "14-csg/keep.frag"),
      resolve_("common/flat.vert", "14-csg/resolve.frag"),
      flat_("common/flat.vert", "14-csg/flat.frag"),
      quadMesh_(makeScreenQuad()),
      quad_(quadMesh_) {
  if (fromFile_ && fromFile_->csg.empty())
    throw UsageError(fromFile_->file.string() +
                     ": the scene has no csg line; lesson 14 renders a CSG expression over the objects");
}

Csg::~Csg() {
  if (work_) glDeleteFramebuffers(1, &work_);
  if (workDepth_) glDeleteTextures(1, &workDepth_);
  if (workColour_) glDeleteRenderbuffers(1, &workColour_);
  if (workPrimitive_) glDeleteTextures(1, &workPrimitive_);
  if (nearest_) glDeleteFramebuffers(1, &nearest_);
  if (nearestDepth_) glDeleteTextures(1, &nearestDepth_);
  if (nearestColour_) glDeleteRenderbuffers(1, &nearestColour_);
  if (nearestPrimitive_) glDeleteTextures(1, &nearestPrimitive_);
}

// The work buffer: a depth and stencil texture the size of the frame, 32-bit float (the merge reads
// the depth), a colour the passes paint the surface into for the pass stepper, and an unsigned
// integer texture (the merge reads it) where the fragment that writes the depth writes its
// primitive's index + 1 (drawSelected). glClear leaves that one undefined: it is read only where
// a target's fragment wrote the depth. The nearest layers' buffer is made the same way: the
// automatic method trims a product's first layer in the work buffer and then swaps the two
// (keepNearest), so either may be the work buffer.
void Csg::workBuffer(glm::ivec2 size) {
  if (work_ && workSize_ == size) return;
  workSize_ = size;
  makeWorkBuffer(size, work_, workDepth_, workColour_, workPrimitive_);
  makeWorkBuffer(size, nearest_, nearestDepth_, nearestColour_, nearestPrimitive_);
}

void Csg::makeWorkBuffer(glm::ivec2 size, GLuint& framebuffer, GLuint& depth, GLuint& colour, GLuint& primitive) {
  if (!framebuffer) {
    glGenFramebuffers(1, &framebuffer);
    glGenTextures(1, &depth);
    glGenRenderbuffers(1, &colour);
    glGenTextures(1, &primitive);
  }
  glBindTexture(GL_TEXTURE_2D, depth);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH32F_STENCIL8, size.x, size.y, 0, GL_DEPTH_STENCIL,
               GL_FLOAT_32_UNSIGNED_INT_24_8_REV, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  glBindTexture(GL_TEXTURE_2D, 0);
  glBindTexture(GL_TEXTURE_2D, primitive);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R32UI, size.x, size.y, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
  glBindRenderbuffer(GL_RENDERBUFFER, colour);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, size.x, size.y);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, primitive, 0);
  const GLenum drawBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, drawBuffers);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("14-csg: the work buffer is incomplete");
  // Its colour, which the pass stepper may show before a pass paints it, starts as the background.
  glClearBufferfv(GL_COLOR, 0, glm::value_ptr(kBackground));
}

// Clears the bound work buffer: its colour (draw buffer 0) to the background, its depth and stencil.
// The primitive texture keeps what it had: glClear's colour bit on an integer texture is undefined
// on the desktop and an error in WebGL 2.
void Csg::clearWork() {
  glClearBufferfv(GL_COLOR, 0, glm::value_ptr(kBackground));
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

// The scene's meshes on the GPU (made again only when the expression changes), its models at the
// frame's time (the spin), the frame they are drawn from, and its expression parsed.
CsgTree Csg::prepare(const CsgScene& scene, const Frame& f) {
  if (scene.expression != preparedFor_) {
    meshes_.clear();
    colours_.clear();
    convex_.clear();
    boxes_.clear();
    spheres_.clear();
    for (const Primitive& p : scene.primitives) {
      meshes_.push_back(std::make_unique<GpuMesh>(p.mesh));
      colours_.push_back(p.colour);
      convex_.push_back(convexMesh(p.mesh));
      glm::vec3 low = p.mesh.positions.front(), high = low;
      for (const glm::vec3& v : p.mesh.positions) low = glm::min(low, v), high = glm::max(high, v);
      boxes_.emplace_back(low, high);
      spheres_.push_back(boundingSphereOf(p.mesh.positions));
    }
    preparedFor_ = scene.expression;
  }
  models_.clear();
  const glm::mat4 spin = glm::rotate(
      glm::mat4(1.0f), glm::radians(scene.spinDegPerSecond * static_cast<float>(f.time)), {0, 1, 0});
  for (const Primitive& p : scene.primitives) models_.push_back(spin * p.model);
  // Drawn from the world's origin while the eye is no farther from it than the solid's farthest
  // point is from the eye (every picture near the origin as before, coincident faces tied as
  // before), else from the eye: each model moved by -eye in double and rounded once, the view the
  // frame's rotation alone. A float rounds a coordinate by 2^-24 of its size, and none is then
  // larger than twice the solid's farthest distance from the eye (in world coordinates 9e5 units
  // out a vertex rounded to 1/16 unit, and Frame::view's translation as much).
  origin_ = glm::vec3(0.0f);
  view_ = f.view;
  double farthest = 0.0;
  for (std::size_t i = 0; i < models_.size(); ++i) {
    const BoundingSphere s = worldSphereOf(static_cast<int>(i));
    farthest = std::max(farthest, glm::distance(glm::dvec3(s.centre), glm::dvec3(f.eye)) + s.radius);
  }
  if (glm::length(glm::dvec3(f.eye)) > farthest) {
    origin_ = f.eye;
    view_ = glm::mat4(glm::mat3(f.view));
    const glm::dmat4 fromEye = glm::translate(glm::dmat4(1.0), -glm::dvec3(origin_));
    for (glm::mat4& m : models_) m = glm::mat4(fromEye * glm::dmat4(m));
  }
  std::vector<std::string> names;
  for (const Primitive& p : scene.primitives) names.push_back(p.name);
  return parseCsg(scene.expression, names);
}

bool Csg::subtracted(const CsgProduct& p, int primitive) {
  return std::binary_search(p.subtracted.begin(), p.subtracted.end(), primitive);
}

// Draws the target faces of `targets` in the product: front faces of the intersected ones,
// back faces of the subtracted ones; in white (Depth: for the depth and stencil alone), lit with
// the primitive recorded in the work buffer (Selected), or lit where the work buffer says the
// fragment is the product's surface (Merged).
void Csg::drawTargets(const CsgProduct& p, const std::vector<int>& targets, Paint paint) {
  for (int x : targets) {
    glCullFace(subtracted(p, x) ? GL_FRONT : GL_BACK);
    if (paint == Paint::Merged)
      drawMerged(x);
    else if (paint == Paint::Selected)
      drawSelected(x);
    else if (paint == Paint::Primitive)
      drawPrimitive(x);
    else
      drawDepth(x);
  }
}

void Csg::setLighting(const Program& p, const Frame& f) const {
  p.set("ambient", glm::vec3(0.25f));
  // World positions less origin_ (prepare): the light and the eye moved with them.
  p.set("light", glm::vec4(glm::vec3(glm::dvec3(3.0, 6.0, 4.0) - glm::dvec3(origin_)), 1.0f));
  p.set("lightColour", glm::vec3(1.0f));
  p.set("eye", glm::vec3(glm::dvec3(f.eye) - glm::dvec3(origin_)));
  p.set("shininess", 24.0f);
}

void Csg::drawDepth(int i) {
  depthOnly_.set("model", models_[static_cast<std::size_t>(i)]);
  depthOnly_.set("colour", glm::vec4(1.0f));
  frontFace(i);
  meshes_[static_cast<std::size_t>(i)]->draw();
}
void Csg::drawShaded(int i) {
  light_.set("model", models_[static_cast<std::size_t>(i)]);
  frontFace(i);
  light_.set("colour", colours_[static_cast<std::size_t>(i)]);
  meshes_[static_cast<std::size_t>(i)]->draw();
}
// Into the work buffer: lit, every fragment kept (the depth and stencil tests choose), its
// primitive written beside its depth.
void Csg::drawSelected(int i) {
  drawWithMergeShader(i, false);
}
// The same, the primitive alone (the automatic method: the work buffer's colour is the pass
// stepper's, and this method paints none).
void Csg::drawPrimitive(int i) {
  select_.set("primitive", i + 1);
  select_.set("model", models_[static_cast<std::size_t>(i)]);
  frontFace(i);
  meshes_[static_cast<std::size_t>(i)]->draw();
}
// Into the frame: lit where the work buffer holds this primitive at exactly this depth.
void Csg::drawMerged(int i) {
  drawWithMergeShader(i, true);
}
void Csg::drawWithMergeShader(int i, bool merging) {
  merge_.set("merging", merging ? 1 : 0);
  merge_.set("primitive", i + 1);
  merge_.set("model", models_[static_cast<std::size_t>(i)]);
  frontFace(i);
  merge_.set("colour", colours_[static_cast<std::size_t>(i)]);
  meshes_[static_cast<std::size_t>(i)]->draw();
}
// The merge (and keep) shader's inputs: the work buffer's depth on texture unit 0, its primitives on 1.
void Csg::mergeInputs() {
  for (Program* p : {&merge_, &keep_, &resolve_}) {
    p->set("productDepth", 0);
    p->set("productPrimitive", 1);
  }
}

// A mirroring model (a negative determinant: scale -1 1 1, OpenSCAD's mirror()) or a mirrored view
// turns primitive i's triangles round on screen: its front faces then wind clockwise there. Both
// together cancel. Every cull and every front/back stencil operation follows this.
//
// Every draw of a primitive the far plane may cut (pastFar_) is depth clamped: its fragments past
// the far plane lie at the far plane's depth instead of being clipped away. A count of the faces
// behind a surface (Goldfeather's parity, SCS's back faces) then misses none of them, and a surface
// there, at the clear depth, is never merged (nearer is strict): the ray cast does not see past the
// far plane either. All its draws, so that the same triangle lands on the same depth in every pass
// (a clamped triangle is not clipped, and its depths round otherwise); only its draws, so that no
// other scene's pixels change. Its fragments before the near plane lie at the near plane's depth,
// in front of every surface: that is the near plane cutting a primitive, which render refuses
// where the result would need a cap there (refuseNearCap).
void Csg::frontFace(int i) {
  const bool mirrored = (glm::determinant(glm::mat3(models_[static_cast<std::size_t>(i)])) < 0.0f) != mirroredView_;
  glFrontFace(mirrored ? GL_CW : GL_CCW);
  const bool clamp = pastFar_[static_cast<std::size_t>(i)];
  if (clamp != depthClamped_) clamp ? glEnable(GL_DEPTH_CLAMP) : glDisable(GL_DEPTH_CLAMP);
  depthClamped_ = clamp;
}

// The frame's state before a method draws. The depth mapping comes first, before anything is
// cleared or drawn: reversed float depth where the driver has clip control (lesson 15), so that a
// depth is held to about 2^-24 of its distance at every distance and surfaces far from a near plane
// close to the eye stay apart; nearer is then greater, and every comparison flips (depth_.less,
// further()...). The frame is cleared here for the two-solid method, which draws straight into it;
// the others clear it at their first merge (clearFrame).
void Csg::beginFrame(const Frame& f, bool clearNow) {
  mirroredView_ = glm::determinant(glm::mat3(view_)) < 0.0f;  // a mirrored camera
  pastFar_.assign(models_.size(), false);  // the primitives the far plane may cut (frontFace)
  for (std::size_t i = 0; i < models_.size(); ++i) pastFar_[i] = reachesPastFar(f, static_cast<int>(i));
  depthClamped_ = false;
  depth_ = depthMappingOf(f);
  if (f.reversedDepth) glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // window depth = clip z / w
  glClearColor(kBackground.r, kBackground.g, kBackground.b, kBackground.a);
  glClearDepth(depth_.farthest);
  glClearStencil(0);
  frameToClear_ = true;
  if (clearNow) clearFrame();
  glEnable(GL_CULL_FACE);  // a solid's front or back faces, one at a time
  const glm::mat4 viewProjection = depth_.projection * view_;
  for (Program* p : {&light_, &depthOnly_, &merge_, &select_}) p->set("viewProjection", viewProjection);
  setLighting(light_, f);
  setLighting(merge_, f);
  light_.set("twoSided", 1);  // back faces kept are seen from inside: lit on that side
}

// GL's defaults again, after a method (and the frame cleared, where no product was merged).
void Csg::endFrame(const Frame& f) {
  if (frameToClear_) {
    glBindFramebuffer(GL_FRAMEBUFFER, f.framebuffer());
    clearFrame();
  }
  glDisable(GL_CULL_FACE);
  if (depthClamped_) glDisable(GL_DEPTH_CLAMP);
  depthClamped_ = false;
  glFrontFace(GL_CCW);
  glCullFace(GL_BACK);
  glDisable(GL_STENCIL_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearDepth(1.0);
  if (f.reversedDepth) glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);  // GL's default mapping
}

// No scissor, both colour attachments drawn to in the nearest-layers and work buffers, the frame's
// framebuffer bound: as a frame starts.
void Csg::unscissorAndDrawToBoth(const Frame& f) {
  glDisable(GL_SCISSOR_TEST);
  const GLenum both[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  for (GLuint buffer : {nearest_, work_}) {
    glBindFramebuffer(GL_FRAMEBUFFER, buffer);
    glDrawBuffers(2, both);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, f.framebuffer());
}

// endFrame from wherever a method stopped: a refusal mid-frame (refuseDeepCount) leaves no state
// behind for the next frame (the window's, drawn with the settings before). The automatic method's
// scissor and draw buffers too.
void Csg::abandonFrame(const Frame& f) {
  unscissorAndDrawToBoth(f);
  glStencilMask(0xFF);
  bindSurface(0, 0);
  endFrame(f);
}

// The bound frame cleared (the background, the far plane, stencil 0), once a frame. Left until the
// first merge, the clear begins the merge's own batch of draws: llvmpipe then sets each tile to the
// clear values as it starts it, where a clear before the work buffer's passes is a batch of its own,
// every tile written out and read back in.
void Csg::clearFrame() {
  if (!frameToClear_) return;
  frameToClear_ = false;
  const bool scissor = glIsEnabled(GL_SCISSOR_TEST);
  glDisable(GL_SCISSOR_TEST);  // the whole frame, whatever the product's rectangle
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glStencilMask(0xFF);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  if (scissor) glEnable(GL_SCISSOR_TEST);
}

// The samples that pass in draw (an occlusion query; a wait for its result), outside the pass
// statistics' own count.
std::uint64_t Csg::samplesPassed(Frame& f, const std::function<void()>& draw) {
  GLuint64 n = 0;
  f.ownOcclusionQueries([&] {
    GLuint query = 0;
    glGenQueries(1, &query);
    glBeginQuery(GL_SAMPLES_PASSED, query);
    draw();
    glEndQuery(GL_SAMPLES_PASSED);
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &n);
    glDeleteQueries(1, &query);
  });
  return n;
}

// A product's surface as the merge, resolve and keep shaders read it: its depth texture on unit 0,
// its primitive texture on unit 1 (0, 0: neither), unit 0 left active.
void Csg::bindSurface(GLuint depth, GLuint primitive) {
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, primitive);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, depth);
}

// The full-screen quad through `program` (its transform the identity), whichever faces are culled.
void Csg::fullScreen(const Program& program) {
  program.set("transform", glm::mat4(1.0f));
  const bool culling = glIsEnabled(GL_CULL_FACE);
  glDisable(GL_CULL_FACE);
  quad_.draw();
  if (culling) glEnable(GL_CULL_FACE);
}

// A full-screen quad at window depth `depth` (0 near and 1 far; reversed, 1 near and 0 far, where
// window depth is the normalized device z itself).
void Csg::drawQuad(const glm::vec4& colour, float depth) {
  const float z = depth_.less == GL_LESS ? 2.0f * depth - 1.0f : depth;
  flat_.set("transform", glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, z)));
  flat_.set("colour", colour);
  const bool culling = glIsEnabled(GL_CULL_FACE);
  glDisable(GL_CULL_FACE);  // the quad covers every pixel whichever faces are being culled
  quad_.draw();
  if (culling) glEnable(GL_CULL_FACE);  // as the caller had it
}

}  // namespace stencil::csg_lesson
