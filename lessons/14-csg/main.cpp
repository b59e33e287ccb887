// Lesson 14: constructive solid geometry with the stencil (Kilgard, "Improving Shadows and
// Reflections via the Stencil Buffer", section 7 and figure 19, the GLUT demo csg.c; Goldfeather,
// Monar, Turk and Fuchs 1989 and Wiegand 1996 for any expression; Stewart, Leach and John 1998
// for the layered count).
//
// A solid made of others is drawn by drawing its primitives' surfaces and keeping the parts that
// lie on the result. Which parts those are is a question of inside and outside, and the stencil
// answers it per pixel: with a surface in the depth buffer, draw a closed solid S with the depth
// test on and count its faces in front of the surface: INCR on S's front faces, DECR on its back
// faces (or INVERT on both: the count's parity). An odd count means the surface lies inside S.
//
// Two convex solids (the demo): the surfaces of
//   A + B   A's and B's front faces, the nearer wins (the depth test alone);
//   A * B   A's front faces inside B, and B's front faces inside A;
//   A - B   A's front faces outside B, and B's back faces inside A;
//   B - A   B's front faces outside A, and A's back faces inside B.
// The demo's sub(a, b), commented "subtract b from a", keeps a's back faces inside b and b's
// front faces outside a: that is b - a, so its menu entries name the difference the other way
// round from the solid it draws. Each surface in turn: its nearest face into a cleared depth,
// the other solid counted, the face drawn again (depth EQUAL) where the count says it belongs,
// tagged in the stencil; what was not kept goes back to the far plane so the next surface is
// not hidden behind it. The first surface of each pair is the nearer wherever both are kept.
//
// Any expression (Goldfeather): normalized to a sum of products (geometry/csg.h), each product
// an intersection of primitives minus others. A product's surface is made of its primitives'
// surfaces, each trimmed by all the others: a target primitive's faces (front faces of an
// intersected one, back faces of a subtracted one) into a cleared depth buffer of its own, then
// per other primitive a parity bit (INVERT where its faces lie in front), then the pixels whose
// bits say "outside an intersected one" or "inside a subtracted one" pushed to the far plane.
// What is left is drawn into the frame where the fragment is that depth, the depth test keeping
// the nearest of all: products merge by depth. A concave target has several faces along a ray;
// the stencil EQUAL k selects the k-th fragment drawn at each pixel (INCR on every fragment), so
// a convexity bound c tries c layers of each target: O(n^2 c) passes for a product of n. Layered
// Goldfeather selects the k-th fragment of all the product's target faces at once, k up to the
// largest depth complexity of those faces (lesson 13's count): k(1 + n) passes. An occlusion
// query that finds a layer empty stops either early.
//
// SCS (Stewart, Leach and John), for convex primitives only: the intersection is entered at the
// furthest of the intersected front faces (if every intersected back face lies behind it), and a
// subtracted primitive moves the surface to its back face where the surface lies inside it; the
// subtracted primitives are applied in a sequence that holds every ordering of them, since they
// may lie along a ray in any order (geometry/csg.h, subtractionSequence).
//
// Goldfeather and SCS build each product's surface in a work buffer of their own; its colour is
// painted for the pass stepper only (the selected layer lit, trimmed pixels the background), so
// stepping through the passes shows the work buffer's colour, depth and stencil at each step.
// Reading order: render, the two solids, Goldfeather, SCS; the scenes, cameras, options and
// variants follow the class, the oracle's hook ends it.

#include <algorithm>
#include <array>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <string>
#include <vector>

#include "geometry/csg.h"
#include "geometry/scene.h"
#include "geometry/shapes.h"
#include "gl/errors.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/shader.h"

using namespace stencil;

namespace {

// The two-solid method's operations (the "op" option), and the methods.
constexpr int kUnion = 0, kIntersection = 1, kAMinusB = 2, kBMinusA = 3;
constexpr int kTwoSolids = 0, kGoldfeather = 1, kLayered = 2, kScs = 3;
// The two-solid method's stencil: bit 0 the count's parity, bits 7 and 6 where A's and B's
// surfaces were kept (the primitive each pixel shows).
constexpr GLuint kParity = 0x01, kKeptA = 0x80, kKeptB = 0x40;
const glm::vec4 kBackground(0.1f, 0.1f, 0.13f, 1.0f);

// A CSG scene: named primitives (closed, outward-wound meshes) and an expression over them.
struct Primitive {
  std::string name;
  Mesh mesh;
  glm::mat4 model;
  glm::vec3 colour;
};
struct CsgScene {
  std::vector<Primitive> primitives;
  std::string expression;
  float spinDegPerSecond = 15.0f;  // the whole solid turns about +y
};

// The scene the options (or --scene's file) ask for, at the frame's time (the scenes follow the
// lesson class).
CsgScene sceneFor(const Frame&, const Scene* fromFile);

class Csg final : public Lesson {
 public:
  explicit Csg(const Scene* fromFile)
      : fromFile_(fromFile),
        light_("common/light.vert", "common/light.frag"),
        depthOnly_("common/light.vert", "common/flat.frag"),
        merge_("common/light.vert", "14-csg/merge.frag"),
        flat_("common/flat.vert", "common/flat.frag"),
        quadMesh_(makeScreenQuad()),
        quad_(quadMesh_) {
    if (fromFile_ && fromFile_->csg.empty())
      throw UsageError(fromFile_->file.string() +
                       ": the scene has no csg line; lesson 14 renders a CSG expression over the objects");
  }

  ~Csg() override {
    if (work_) glDeleteFramebuffers(1, &work_);
    if (workDepth_) glDeleteTextures(1, &workDepth_);
    if (workColour_) glDeleteRenderbuffers(1, &workColour_);
  }

  void render(Frame& f) override {
    const int method = f.option("method");
    const CsgScene scene = sceneFor(f, fromFile_);
    const CsgTree tree = prepare(scene, f.time);

    glClearColor(kBackground.r, kBackground.g, kBackground.b, kBackground.a);
    glClearDepth(1.0);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_CULL_FACE);  // a solid's front or back faces, one at a time
    const glm::mat4 viewProjection = f.projection * f.view;
    for (Program* p : {&light_, &depthOnly_, &merge_}) p->set("viewProjection", viewProjection);
    setLighting(light_, f);
    setLighting(merge_, f);
    light_.set("twoSided", 1);  // back faces kept are seen from inside: lit on that side

    if (method == kTwoSolids)
      twoSolidsMethod(f, scene, f.option("op"));
    else if (method == kScs)
      scs(f, normalize(tree));
    else
      goldfeather(f, normalize(tree), method == kLayered);

    glDisable(GL_CULL_FACE);  // GL's defaults again
    glCullFace(GL_BACK);
    glDisable(GL_STENCIL_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    if (f.on("oracle")) checkAgainstRayCast(f, scene, tree, method);
  }

 private:
  // ---- two convex solids (the demo) -------------------------------------------------------------

  // One surface of the pair: `faces` (GL_FRONT or GL_BACK) of primitive x where it lies inside
  // (wantInside) or outside solid s, tagged with `kept` in the stencil. Pixels already tagged
  // belong to the nearer surface of the pair and are left alone.
  void keepSurface(Frame& f, int x, GLenum faces, int s, bool wantInside, GLuint kept, bool trim) {
    const GLuint tagged = kKeptA | kKeptB;
    // 1. The surface's nearest face into the depth buffer, where no surface is kept yet.
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // depth only
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);  // the nearest of x's chosen faces
    glDepthMask(GL_TRUE);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 0, tagged);                  // not where the nearer surface was kept
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);              // nothing counted yet
    glCullFace(faces == GL_FRONT ? GL_BACK : GL_FRONT);  // only the chosen faces are drawn
    drawDepth(x);
    f.pass("surface");

    // 2. Count s's faces in front of it: INCR on its front faces, DECR on its back faces. s is
    // convex: where its back face is in front, so is its front face, and the count never goes
    // below 0 (DECR would stop there). Bit 0 of the count is 1 inside s.
    glDepthMask(GL_FALSE);  // s is only counted, never a surface here
    glStencilMask(kParity);
    glStencilFunc(GL_ALWAYS, 0, 0);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);  // s's front face in front of the surface: entering s
    glCullFace(GL_BACK);
    drawDepth(s);
    glStencilOp(GL_KEEP, GL_KEEP, GL_DECR);  // its back face in front: leaving s again
    glCullFace(GL_FRONT);
    drawDepth(s);
    f.pass("count");

    // 3. Keep: x's face again, shaded, where the depth is its own and the count says in (or out),
    // and no surface is kept yet; INVERT sets the kept bit there.
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthFunc(GL_EQUAL);  // exactly the face drawn in step 1
    glStencilMask(kept);
    glStencilFunc(GL_EQUAL, wantInside ? kParity : 0, trim ? (tagged | kParity) : tagged);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);  // tag the pixel as x's
    glCullFace(faces == GL_FRONT ? GL_BACK : GL_FRONT);
    drawShaded(x);
    f.pass("keep");

    // 4. Where x's face was not kept its depth would hide the next surface: back to the far plane.
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthFunc(GL_ALWAYS);  // every untagged pixel, whatever lies there
    glDepthMask(GL_TRUE);
    glStencilMask(0);                    // the tags stay
    glStencilFunc(GL_EQUAL, 0, tagged);  // no surface kept here
    farQuad();
    glStencilMask(kParity);  // the parity starts again at 0 for the next surface
    glClear(GL_STENCIL_BUFFER_BIT);
    glStencilMask(0xFF);
    f.pass("far");
  }

  void twoSolidsMethod(Frame& f, const CsgScene&, int op) {
    const bool trim = f.on("stencil");
    constexpr int a = 0, b = 1;
    if (op == kUnion) {
      // Both solids, the nearer surface wins; the stencil only records whose surface it is.
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_LESS);
      glEnable(GL_STENCIL_TEST);
      glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);  // the last surface written is the nearest
      glCullFace(GL_BACK);
      glStencilFunc(GL_ALWAYS, kKeptA, 0xFF);
      drawShaded(a);
      glStencilFunc(GL_ALWAYS, kKeptB, 0xFF);
      drawShaded(b);
      f.pass("keep");
      return;
    }
    // Each pair in the order that puts the nearer surface first where both are kept.
    if (op == kIntersection) {
      keepSurface(f, a, GL_FRONT, b, true, kKeptA, trim);
      keepSurface(f, b, GL_FRONT, a, true, kKeptB, trim);
    } else if (op == kAMinusB) {
      keepSurface(f, a, GL_FRONT, b, false, kKeptA, trim);
      keepSurface(f, b, GL_BACK, a, true, kKeptB, trim);
    } else {
      keepSurface(f, b, GL_FRONT, a, false, kKeptB, trim);
      keepSurface(f, a, GL_BACK, b, true, kKeptA, trim);
    }
  }

  // ---- Goldfeather ------------------------------------------------------------------------------

  // One product's surface, one target at a time (or, layered, all its targets at once), into
  // the work buffer's depth, trimmed there, merged into the frame.
  void goldfeather(Frame& f, const SumOfProducts& sop, bool layered) {
    f.count("products", sop.products.size());
    f.count("literals", sop.literals());
    f.count("products_before_pruning", sop.productsBeforePruning);
    for (const char* name : {"select_passes", "parity_passes", "far_passes", "merge_passes", "layers"})
      f.count(name, 0);
    workBuffer(f.size);
    merge_.set("productDepth", 0);
    merge_.set("tolerance", 1e-6f);
    for (const CsgProduct& product : sop.products) {
      std::vector<int> targets = product.intersected;
      targets.insert(targets.end(), product.subtracted.begin(), product.subtracted.end());
      if (layered) {
        const int k = f.on("queries") ? 255 : productDepthComplexity(f, product);
        for (int layer = 0; layer < k; ++layer)
          if (!trimLayer(f, product, targets, targets, layer)) break;
      } else {
        for (int x : targets) {
          std::vector<int> others;
          for (int y : targets)
            if (y != x) others.push_back(y);
          for (int layer = 0; layer < f.option("convexity"); ++layer)
            if (!trimLayer(f, product, {x}, others, layer)) break;
        }
      }
    }
    // The frame again: a layer found empty (queries) ends in the work buffer.
    glBindFramebuffer(GL_FRAMEBUFFER, f.framebuffer());
  }

  // Layer `layer` of the targets' faces, trimmed by `trimmers` and merged into the frame. Returns
  // false when an occlusion query found the layer empty (with the queries option): no later layer
  // has a fragment either.
  bool trimLayer(Frame& f, const CsgProduct& p, const std::vector<int>& targets,
                 const std::vector<int>& trimmers, int layer) {
    glBindFramebuffer(GL_FRAMEBUFFER, work_);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilMask(0xFF);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    // 1. Select: the layer-th fragment drawn at each pixel. Every fragment INCRs the stencil, and
    // only the one that finds it EQUAL to layer writes its depth (and its colour: the work
    // buffer's colour is no part of the method, it shows the surface to the pass stepper).
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);  // in draw order, not depth order: every fragment is some layer
    glDepthMask(GL_TRUE);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, std::min(layer, 255), 0xFF);
    glStencilOp(GL_INCR, GL_INCR, GL_INCR);  // each fragment counts, passing or not
    std::uint64_t selected = 1;
    if (f.on("queries")) {
      f.ownOcclusionQueries([&] {
        GLuint query = 0;
        glGenQueries(1, &query);
        glBeginQuery(GL_SAMPLES_PASSED, query);
        drawTargets(p, targets, Paint::Lit);
        glEndQuery(GL_SAMPLES_PASSED);
        GLuint64 n = 0;
        glGetQueryObjectui64v(query, GL_QUERY_RESULT, &n);
        glDeleteQueries(1, &query);
        selected = n;
      });
    } else {
      drawTargets(p, targets, Paint::Lit);
    }
    f.count("select_passes");
    f.pass("select");
    if (selected == 0) return false;
    f.count("layers");  // a layer with fragments, trimmed and merged

    // 2. Parity: one stencil bit per trimming primitive, INVERT where its faces lie in front of
    // the selected surface or on it (LEQUAL: a surface counts as inside the intersected
    // primitive it belongs to and outside the subtracted one). After 8 bits, or the last, the
    // pixels whose bits are not the product's (1 inside an intersected primitive, 0 outside a
    // subtracted one) go to the far plane, and the bits start again. The last batch's bits stay
    // in the stencil for the pass stepper.
    glClear(GL_STENCIL_BUFFER_BIT);
    glDisable(GL_CULL_FACE);  // every face of a trimming primitive counts
    std::size_t bit = 0;
    GLuint expected = 0;
    for (std::size_t i = 0; i < trimmers.size(); ++i) {
      const int y = trimmers[i];
      if (f.on("stencil")) {
        glDepthFunc(GL_LEQUAL);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDepthMask(GL_FALSE);  // counted, not drawn
        glStencilMask(1u << bit);
        glStencilFunc(GL_ALWAYS, 0, 0);
        glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);  // the parity of y's faces in front
        drawDepth(y);
        f.count("parity_passes");
        if (!subtracted(p, y)) expected |= 1u << bit;
        ++bit;
      }
      if (bit == 8 || (i + 1 == trimmers.size() && bit > 0)) {
        glDepthFunc(GL_ALWAYS);  // the failing pixels, whatever their depth
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDepthMask(GL_TRUE);
        glStencilMask(0);
        glStencilFunc(GL_NOTEQUAL, expected, (1u << bit) - 1u);
        farQuad();
        f.count("far_passes");
        glStencilMask(0xFF);
        if (i + 1 < trimmers.size()) glClear(GL_STENCIL_BUFFER_BIT);
        bit = 0;
        expected = 0;
      }
    }
    glEnable(GL_CULL_FACE);
    f.pass("parity");

    // 3. Merge: the targets drawn into the frame where they are the trimmed surface.
    mergeIntoFrame(f, p, targets);
    return true;
  }

  // Merge: the targets drawn into the frame where they are the trimmed surface (the shader
  // compares with the work depth), the nearest of all products winning; the stencil records
  // the primitive (its index modulo 255, + 1).
  void mergeIntoFrame(Frame& f, const CsgProduct& p, const std::vector<int>& targets) {
    glBindFramebuffer(GL_FRAMEBUFFER, f.framebuffer());
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, workDepth_);
    for (int x : targets) {
      glStencilFunc(GL_ALWAYS, x % 255 + 1, 0xFF);  // the primitive, modulo 255, for the oracle
      drawTargets(p, {x}, Paint::Merged);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    f.count("merge_passes");
    f.pass("merge");
  }

  // Lesson 13's count on the product's target faces: INCR on every fragment, the depth test
  // off; the largest count, found by bisection with stencil LESS and occlusion queries, is the
  // number of layers the layered method needs.
  int productDepthComplexity(Frame& f, const CsgProduct& p) {
    glBindFramebuffer(GL_FRAMEBUFFER, work_);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilMask(0xFF);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // the count alone
    glDisable(GL_DEPTH_TEST);                             // every fragment counts
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    std::vector<int> targets = p.intersected;
    targets.insert(targets.end(), p.subtracted.begin(), p.subtracted.end());
    drawTargets(p, targets, Paint::Depth);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    int low = 0, high = 255;  // the largest count lies in [low, high]
    f.ownOcclusionQueries([&] {
      GLuint query = 0;
      glGenQueries(1, &query);
      while (low < high) {
        const int middle = (low + high) / 2;
        glStencilFunc(GL_LESS, middle, 0xFF);  // passes where middle < count
        glBeginQuery(GL_SAMPLES_PASSED, query);
        drawQuad(glm::vec4(0.0f), 0.0f);
        glEndQuery(GL_SAMPLES_PASSED);
        GLuint64 n = 0;
        glGetQueryObjectui64v(query, GL_QUERY_RESULT, &n);
        if (n > 0)
          low = middle + 1;
        else
          high = middle;
      }
      glDeleteQueries(1, &query);
    });
    glEnable(GL_DEPTH_TEST);
    f.count("layers_counted", static_cast<std::uint64_t>(low));
    f.pass("layers");
    return low;
  }

  // ---- SCS ---------------------------------------------------------------------------------------

  // Per product, in the work buffer: the intersection of its intersected primitives as the
  // furthest front face that no back face lies in front of (convex primitives: that is where the
  // ray enters all of them), then each subtracted primitive in the order of the subtraction
  // sequence moves the surface to its back face where the surface lies inside it, then the
  // intersection clips again; the surface is merged into the frame as Goldfeather's is.
  void scs(Frame& f, const SumOfProducts& sop) {
    f.count("products", sop.products.size());
    f.count("literals", sop.literals());
    for (const char* name : {"sequence_length", "subtraction_passes", "clip_passes", "merge_passes"})
      f.count(name, 0);
    workBuffer(f.size);
    merge_.set("productDepth", 0);
    merge_.set("tolerance", 1e-6f);
    for (const CsgProduct& p : sop.products) {
      glBindFramebuffer(GL_FRAMEBUFFER, work_);
      // The work buffer's colour follows the surface as it moves (no part of the method: the
      // pass stepper's picture of it).
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      glEnable(GL_DEPTH_TEST);
      glEnable(GL_STENCIL_TEST);
      glStencilMask(0xFF);
      glClearDepth(0.0);  // the furthest front face wins: start at the near plane
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
      glClearDepth(1.0);
      // 1. The intersected primitives' front faces, the furthest kept: where the ray has entered
      // them all, if it is inside them all there.
      glDepthFunc(GL_GREATER);
      glDepthMask(GL_TRUE);
      glStencilFunc(GL_ALWAYS, 0, 0);
      glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
      glCullFace(GL_BACK);
      for (int a : p.intersected) drawShaded(a);
      clipByIntersection(f, p);
      f.pass("intersect");
      // 2. The subtraction sequence: where the surface lies inside s (s's front face in front of
      // it, its back face behind), the surface moves back to s's back face.
      const std::vector<int> order = subtractionSequence(static_cast<int>(p.subtracted.size()));
      f.count("sequence_length", order.size());
      for (int i : order) {
        const int s = p.subtracted[static_cast<std::size_t>(i)];
        glStencilMask(0xFF);
        glClear(GL_STENCIL_BUFFER_BIT);
        glDepthFunc(GL_LESS);  // s's front face in front of the surface
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDepthMask(GL_FALSE);
        glStencilFunc(GL_ALWAYS, 1, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        glCullFace(GL_BACK);
        drawDepth(s);
        glDepthFunc(GL_GREATER);  // and its back face behind it: the surface is inside s
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDepthMask(GL_TRUE);  // it moves to that back face
        glStencilFunc(GL_EQUAL, 1, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        glCullFace(GL_FRONT);
        drawShaded(s);
        f.count("subtraction_passes", 2);
      }
      f.pass("subtract");
      // 3. A surface moved past an intersected primitive's back face left the intersection.
      clipByIntersection(f, p);
      f.pass("intersect");
      // 4. Merge, as Goldfeather does.
      std::vector<int> targets = p.intersected;
      targets.insert(targets.end(), p.subtracted.begin(), p.subtracted.end());
      mergeIntoFrame(f, p, targets);
    }
  }

  // Counts the intersected primitives whose back face lies behind the surface (or on it) and sends
  // every pixel where that is not all of them to the far plane: the surface lies outside one, or a
  // primitive does not cover the pixel at all (no back face to count; checking for a back face in
  // front would miss that one).
  void clipByIntersection(Frame& f, const CsgProduct& p) {
    glStencilMask(0xFF);
    glClear(GL_STENCIL_BUFFER_BIT);
    glDepthFunc(GL_GEQUAL);  // the back face behind the surface: the surface is before it leaves
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glStencilFunc(GL_ALWAYS, 0, 0);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    glCullFace(GL_FRONT);
    for (int a : p.intersected) drawDepth(a);
    glDepthFunc(GL_ALWAYS);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0);
    glStencilFunc(GL_NOTEQUAL, static_cast<GLint>(std::min<std::size_t>(p.intersected.size(), 255)), 0xFF);
    farQuad();
    glStencilMask(0xFF);
    f.count("clip_passes");
  }

  // The work buffer: a depth and stencil texture the size of the frame (the merge reads the
  // depth), and a colour the passes paint the surface into for the pass stepper.
  void workBuffer(glm::ivec2 size) {
    if (work_ && workSize_ == size) return;
    if (!work_) {
      glGenFramebuffers(1, &work_);
      glGenTextures(1, &workDepth_);
      glGenRenderbuffers(1, &workColour_);
    }
    workSize_ = size;
    glBindTexture(GL_TEXTURE_2D, workDepth_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH32F_STENCIL8, size.x, size.y, 0, GL_DEPTH_STENCIL,
                 GL_FLOAT_32_UNSIGNED_INT_24_8_REV, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindRenderbuffer(GL_RENDERBUFFER, workColour_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, size.x, size.y);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, work_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, workDepth_, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, workColour_);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("14-csg: the work buffer is incomplete");
  }

  // ---- drawing ----------------------------------------------------------------------------------

  // The scene's meshes on the GPU (made again only when the expression changes), its models at
  // `time` (the spin), and its expression parsed.
  CsgTree prepare(const CsgScene& scene, double time) {
    if (scene.expression != preparedFor_) {
      meshes_.clear();
      colours_.clear();
      for (const Primitive& p : scene.primitives) {
        meshes_.push_back(std::make_unique<GpuMesh>(p.mesh));
        colours_.push_back(p.colour);
      }
      preparedFor_ = scene.expression;
    }
    models_.clear();
    const glm::mat4 spin = glm::rotate(
        glm::mat4(1.0f), glm::radians(scene.spinDegPerSecond * static_cast<float>(time)), {0, 1, 0});
    for (const Primitive& p : scene.primitives) models_.push_back(spin * p.model);
    std::vector<std::string> names;
    for (const Primitive& p : scene.primitives) names.push_back(p.name);
    return parseCsg(scene.expression, names);
  }

  static bool subtracted(const CsgProduct& p, int primitive) {
    return std::binary_search(p.subtracted.begin(), p.subtracted.end(), primitive);
  }

  // Draws the target faces of `targets` in the product: front faces of the intersected ones,
  // back faces of the subtracted ones; in white (Depth: for the depth and stencil alone), lit, or
  // lit where the work depth says the fragment is the product's surface (Merged).
  enum class Paint { Depth, Lit, Merged };
  void drawTargets(const CsgProduct& p, const std::vector<int>& targets, Paint paint) {
    for (int x : targets) {
      glCullFace(subtracted(p, x) ? GL_FRONT : GL_BACK);
      if (paint == Paint::Merged)
        drawMerged(x);
      else if (paint == Paint::Lit)
        drawShaded(x);
      else
        drawDepth(x);
    }
  }

  void setLighting(const Program& p, const Frame& f) const {
    p.set("ambient", glm::vec3(0.25f));
    p.set("light", glm::vec4(3.0f, 6.0f, 4.0f, 1.0f));
    p.set("lightColour", glm::vec3(1.0f));
    p.set("eye", f.eye);
    p.set("shininess", 24.0f);
  }

  void drawDepth(int i) {
    depthOnly_.set("model", models_[static_cast<std::size_t>(i)]);
    depthOnly_.set("colour", glm::vec4(1.0f));
    meshes_[static_cast<std::size_t>(i)]->draw();
  }
  void drawShaded(int i) {
    light_.set("model", models_[static_cast<std::size_t>(i)]);
    light_.set("colour", colours_[static_cast<std::size_t>(i)]);
    meshes_[static_cast<std::size_t>(i)]->draw();
  }
  void drawMerged(int i) {
    merge_.set("model", models_[static_cast<std::size_t>(i)]);
    merge_.set("colour", colours_[static_cast<std::size_t>(i)]);
    meshes_[static_cast<std::size_t>(i)]->draw();
  }

  // A full-screen quad at window depth `depth` (0 near, 1 far).
  void drawQuad(const glm::vec4& colour, float depth) {
    flat_.set("transform", glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 2.0f * depth - 1.0f)));
    flat_.set("colour", colour);
    const bool culling = glIsEnabled(GL_CULL_FACE);
    glDisable(GL_CULL_FACE);  // the quad covers every pixel whichever faces are being culled
    quad_.draw();
    if (culling) glEnable(GL_CULL_FACE);  // as the caller had it
  }
  // Back to the far plane, the background's colour where colour is written.
  void farQuad() { drawQuad(kBackground, 1.0f); }

  // ---- test hooks: the oracle --------------------------------------------------------------------

  // The frame's depth and the primitive its stencil records, against the CSG ray cast.
  void checkAgainstRayCast(Frame& f, const CsgScene& scene, const CsgTree& tree, int method) const {
    std::vector<CsgPrimitive> primitives;
    for (std::size_t i = 0; i < scene.primitives.size(); ++i)
      primitives.push_back({&scene.primitives[i].mesh, models_[i]});
    CsgImage expected = rayCastCsg(primitives, tree, f.projection * f.view, f.size);
    // 8 stencil bits record the primitive modulo 255 (0 is none): past 254 primitives the ray
    // cast's are compared modulo 255 too.
    if (method != kTwoSolids)
      for (int& e : expected.primitive)
        if (e >= 0) e %= 255;
    const std::size_t w = static_cast<std::size_t>(f.size.x), h = static_cast<std::size_t>(f.size.y);
    std::vector<float> depthRows(w * h);
    std::vector<std::uint8_t> stencilRows(w * h);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, f.framebuffer());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, f.size.x, f.size.y, GL_DEPTH_COMPONENT, GL_FLOAT, depthRows.data());
    glReadPixels(0, 0, f.size.x, f.size.y, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencilRows.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    std::vector<float> depth(w * h);
    std::vector<int> primitive(w * h);
    for (std::size_t i = 0; i < w * h; ++i) {
      const std::size_t row = (h - 1 - i / w) * w + i % w;  // GL's rows bottom up, the ray cast's top down
      depth[i] = depthRows[row];
      const std::uint8_t s = stencilRows[row];
      if (method == kTwoSolids)
        primitive[i] = (s & kKeptA) ? 0 : (s & kKeptB) ? 1 : kNoSurface;
      else
        primitive[i] = s == 0 ? kNoSurface : s - 1;
    }
    // Depth in window units: the fixed-point buffer's steps are 2^-24; the tolerance allows for
    // the rasterizer's interpolation against the exact intersection.
    const CsgReport r = compareCsg(expected, depth, primitive, 1e-4f);
    f.count("oracle_pixels", r.pixels);
    f.count("oracle_primitive_disagreements", r.primitiveDisagreements);
    f.count("oracle_depth_disagreements", r.depthDisagreements);
    f.count("oracle_on_edges", r.onEdges);
    f.count("oracle_largest_depth_error_1e9", static_cast<std::uint64_t>(r.largestDepthError * 1e9f));
  }

  const Scene* fromFile_;  // --scene's file, or nullptr for the lesson's own scenes
  Program light_, depthOnly_, merge_, flat_;
  Mesh quadMesh_;
  GpuMesh quad_;
  std::vector<std::unique_ptr<GpuMesh>> meshes_;
  std::vector<glm::vec3> colours_;
  std::vector<glm::mat4> models_;
  std::string preparedFor_;
  GLuint work_ = 0, workDepth_ = 0, workColour_ = 0;
  glm::ivec2 workSize_{0};
};

// ---- the lesson's scenes, cameras, options and variants ------------------------------------------

CsgScene twoSolids(int op) {
  using glm::translate;
  const glm::mat4 id(1.0f);
  CsgScene s;
  s.primitives.push_back(
      {"A", makeCube(0.8f), glm::rotate(id, glm::radians(25.0f), {0, 1, 0}), {0.95f, 0.55f, 0.2f}});
  s.primitives.push_back(
      {"B", makeSphere(0.85f, 48, 24), translate(id, {0.95f, 0.45f, 0.25f}), {0.25f, 0.5f, 0.95f}});
  const char* ops[] = {"A + B", "A * B", "A - B", "B - A"};
  s.expression = ops[op];
  return s;
}

CsgScene goldfeatherScene(int scene, int op, int side) {
  using glm::rotate;
  using glm::translate;
  const glm::mat4 id(1.0f);
  CsgScene s;
  switch (scene) {
    case 0: return twoSolids(op);
    case 1: {  // the rounded cube with three holes through it
      s.primitives.push_back({"cube", makeCube(1.0f), id, {0.95f, 0.55f, 0.2f}});
      s.primitives.push_back({"sphere", makeSphere(1.35f, 48, 24), id, {0.25f, 0.5f, 0.95f}});
      const Mesh cylinder = makeCylinder(0.55f, 3.0f, 32);
      s.primitives.push_back(
          {"x", cylinder, rotate(id, glm::radians(90.0f), {0, 0, 1}), {0.3f, 0.8f, 0.35f}});
      s.primitives.push_back({"y", cylinder, id, {0.85f, 0.3f, 0.6f}});
      s.primitives.push_back(
          {"z", cylinder, rotate(id, glm::radians(90.0f), {1, 0, 0}), {0.9f, 0.85f, 0.3f}});
      s.expression = "cube * sphere - (x + y + z)";
      return s;
    }
    case 2:  // a corner scooped out of a cube, a small cube left standing in the scoop
      s.primitives.push_back({"A", makeCube(0.9f), id, {0.95f, 0.55f, 0.2f}});
      s.primitives.push_back(
          {"B", makeSphere(0.95f, 48, 24), translate(id, {0.7f, 0.7f, 0.7f}), {0.25f, 0.5f, 0.95f}});
      s.primitives.push_back(
          {"C", makeCube(0.3f), translate(id, {0.55f, 0.55f, 0.55f}), {0.3f, 0.8f, 0.35f}});
      s.expression = "A - (B - C)";
      return s;
    case 4: {  // OpenCSG's benchmark: a box minus a grid of spheres (5x5: 25 trimmers per target)
      s.primitives.push_back(
          {"box", makeCube(1.0f), glm::scale(id, {1.3f, 0.4f, 1.3f}), {0.95f, 0.55f, 0.2f}});
      s.expression = "box";
      const Mesh sphere = makeSphere(0.3f, 24, 12);
      const auto place = [side](int j) {  // -1..1 across the box, the middle for one
        return side == 1 ? 0.0f : -1.0f + 2.0f * static_cast<float>(j) / static_cast<float>(side - 1);
      };
      for (int i = 0; i < side * side; ++i) {
        const std::string name = "s" + std::to_string(i);
        const glm::vec3 at(place(i % side), 0.4f, place(i / side));
        s.primitives.push_back({name, sphere, translate(id, at), {0.25f, 0.5f, 0.95f}});
        s.expression += " - " + name;
      }
      return s;
    }
    case 5:
    case 6: {  // a pocket whose floor is B's and whose top lies in A's top face (5), or 0.01 above it (6)
      const float grow = scene == 6 ? 0.01f : 0.0f;
      s.primitives.push_back({"A", makeCube(0.8f), id, {0.95f, 0.55f, 0.2f}});
      s.primitives.push_back(
          {"B",
           makeCube(1.0f),
           glm::scale(translate(id, {0.3f, 0.5f + 0.5f * grow, 0.3f}), {0.35f, 0.3f + 0.5f * grow, 0.35f}),
           {0.25f, 0.5f, 0.95f}});
      s.expression = "A - B";
      return s;
    }
    case 7: {  // OpenCSG's cube rack: a box minus 7x7x7 small boxes, the outer ones cutting its faces
      s.primitives.push_back({"box", makeCube(0.9f), id, {0.95f, 0.55f, 0.2f}});
      s.expression = "box";
      const Mesh cube = makeCube(0.1f);
      const auto place = [](int j) { return -1.0f + (2.0f * static_cast<float>(j) + 1.0f) / 7.0f; };
      for (int i = 0; i < 343; ++i) {
        const std::string name = "c" + std::to_string(i);
        s.primitives.push_back({name,
                                cube,
                                translate(id, {place(i % 7), place(i / 7 % 7), place(i / 49)}),
                                {0.25f, 0.5f, 0.95f}});
        s.expression += " - " + name;
      }
      return s;
    }
    case 8: {  // OpenCSG's 3x3x3 grid: a box minus 27 spheres, the outer ones cutting its faces
      s.primitives.push_back({"box", makeCube(0.9f), id, {0.95f, 0.55f, 0.2f}});
      s.expression = "box";
      const Mesh sphere = makeSphere(0.32f, 24, 12);
      for (int i = 0; i < 27; ++i) {
        const std::string name = "s" + std::to_string(i);
        const glm::vec3 at(0.9f * static_cast<float>(i % 3 - 1), 0.9f * static_cast<float>(i / 3 % 3 - 1),
                           0.9f * static_cast<float>(i / 9 - 1));
        s.primitives.push_back({name, sphere, translate(id, at), {0.25f, 0.5f, 0.95f}});
        s.expression += " - " + name;
      }
      return s;
    }
    default:  // a ring cut through on its near side: the far side shows through the cut
      s.primitives.push_back({"T",
                              makeTorus(1.1f, 0.4f, 48, 24),
                              rotate(id, glm::radians(-28.0f), {1, 0, 0}),
                              {0.95f, 0.55f, 0.2f}});
      s.primitives.push_back({"B",
                              makeCube(0.5f),
                              glm::scale(translate(id, {0.3f, 0.2f, 1.05f}), {0.8f, 1.6f, 1.2f}),
                              {0.25f, 0.5f, 0.95f}});
      s.expression = "T - B";
      s.spinDegPerSecond = 0.0f;  // the cut stays in front
      return s;
  }
}

// A scene file's csg line (docs/scenes.md) over its objects, at their models at `time`; the
// file's own motion (spin, bob) turns them, so the lesson adds none.
CsgScene fileScene(const Scene& file, double time) {
  CsgScene s;
  for (const SceneObject& o : file.objects)
    s.primitives.push_back({o.name, o.mesh, o.modelAt(time), o.colour});
  s.expression = file.csg;
  s.spinDegPerSecond = 0.0f;
  return s;
}

CsgScene sceneFor(const Frame& f, const Scene* fromFile) {
  const int method = f.option("method");
  if (fromFile && method == kTwoSolids)
    throw UsageError(
        "--scene: method 0 draws the demo's two solids; the scene's csg expression needs "
        "--set method=1, 2 or 3");
  if (fromFile) return fileScene(*fromFile, f.time);
  if (method == kTwoSolids) return twoSolids(f.option("op"));
  return goldfeatherScene(f.option("scene"), f.option("op"), f.option("grid"));
}

// Low over the ring's near side, looking through the cut at the far side: two front faces of
// the torus along those rays.
OrbitCamera throughTheCut() {
  OrbitCamera c;
  c.target = {0.0f, 0.0f, 0.0f};
  c.distance = 5.0f;
  c.azimuthDeg = 15.0f;
  c.elevationDeg = 16.0f;
  c.farPlane = 30.0f;
  return c;
}

// From A's side of B: the bite A takes out of B faces this way.
OrbitCamera fromTheLeft() {
  OrbitCamera c;
  c.target = {0.45f, 0.2f, 0.1f};
  c.distance = 5.5f;
  c.azimuthDeg = -55.0f;
  c.elevationDeg = 30.0f;
  c.farPlane = 30.0f;
  return c;
}

// The eye inside B, outside A, looking at A: B's front faces lie behind the eye, only its back
// faces are drawn in front of A.
OrbitCamera insideB() {
  OrbitCamera c;
  c.target = {0.0f, 0.0f, 0.0f};
  c.distance = 1.78f;  // the eye 0.7 from B's centre, on the far side from A; B's radius 0.85
  c.azimuthDeg = 75.4f;
  c.elevationDeg = 24.6f;
  c.fovyDeg = 70.0f;
  c.farPlane = 30.0f;
  return c;
}

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "14-csg";
  info.title = "Constructive solid geometry";
  info.summary =
      "Which faces of a solid lie inside another, counted in the stencil: union, intersection and\n"
      "differences of two convex solids; any expression as a sum of products by Goldfeather's parity bits,\n"
      "with a convexity bound or the layered count, or by SCS's subtraction sequences.";
  info.options = {
      {"method", 'M',
       "0 two convex solids (the demo), 1 Goldfeather, 2 layered Goldfeather,\n"
       "      3 SCS (convex primitives only)",
       kTwoSolids, 3},
      {"op", 'O', "two solids: 0 A + B, 1 A * B, 2 A - B, 3 B - A", kAMinusB, 3},
      {"scene", 'N',
       "the scene of methods 1 to 3: 0 the two solids (by op), 1 cube * sphere - three cylinders,\n"
       "      2 A - (B - C), 3 a torus (convexity 2) minus a box, 4 a box minus a grid of spheres,\n"
       "      5 a pocket whose top lies in A's top face (coincident faces), 6 the same, B 0.01 taller,\n"
       "      7 the cube rack: a box minus 343 boxes, 8 a box minus a 3x3x3 grid of spheres",
       0, 8},
      {"grid", 'G', "scene 4: spheres along each side of the grid (the sweep's primitive count)", 5, 7, 1},
      {"convexity", 'C', "Goldfeather: the layers tried per target primitive (its convexity bound)", 1, 8, 1},
      {"queries", 'Q', "Goldfeather: stop at the first layer an occlusion query finds empty", 0},
      {"stencil", 'T', "trim by the stencil (off: every candidate surface kept, the result wrong)", 1},
      {"oracle", 'K',
       "check the depth and the primitive each pixel shows against a CPU CSG ray cast\n"
       "      (--stats reports oracle_*)",
       0},
  };
  info.variants = {
      {"a-minus-b", "A - B: A's front faces outside B, B's back faces inside A", {}},
      {"union", "A + B: both drawn, the depth test alone", {{"op", kUnion}}},
      {"intersection", "A * B: A's front faces inside B, B's inside A", {{"op", kIntersection}}},
      {"b-minus-a",
       "B - A: B's front faces outside A, A's back faces inside B, seen from A's side",
       {{"op", kBMinusA}},
       {},
       fromTheLeft()},
      {"no-stencil", "A - B without the count: A's front and B's back faces all kept", {{"stencil", 0}}},
      {"goldfeather", "A - B by Goldfeather's parity bits: the same picture", {{"method", kGoldfeather}}},
      {"goldfeather-rounded-cube",
       "cube * sphere - three cylinders: one product of five",
       {{"method", kGoldfeather}, {"scene", 1}}},
      {"goldfeather-nested",
       "A - (B - C) = A - B + A * C: two products merged by depth",
       {{"method", kGoldfeather}, {"scene", 2}}},
      {"goldfeather-torus-convexity-1",
       "a torus minus a box with a convexity bound of 1: the torus' second layer never tried",
       {{"method", kGoldfeather}, {"scene", 3}},
       {},
       throughTheCut()},
      {"goldfeather-torus",
       "the torus with a convexity bound of 2",
       {{"method", kGoldfeather}, {"scene", 3}, {"convexity", 2}},
       {},
       throughTheCut()},
      {"layered-torus",
       "layered Goldfeather on the torus: k from the layers' depth complexity",
       {{"method", kLayered}, {"scene", 3}},
       {},
       throughTheCut()},
      {"layered-rounded-cube",
       "layered Goldfeather on the rounded cube",
       {{"method", kLayered}, {"scene", 1}}},
      {"eye-in-b", "A - B with the eye inside B: the count starts at 0 outside B", {}, {}, insideB()},
      {"goldfeather-eye-in-b",
       "Goldfeather's A - B with the eye inside B",
       {{"method", kGoldfeather}},
       {},
       insideB()},
      {"scs-rounded-cube",
       "SCS: the intersection by counting, the cylinders by a subtraction sequence",
       {{"method", kScs}, {"scene", 1}}},
      {"scs-grid",
       "SCS on the box minus 25 spheres: a sequence of 25 * 24 + 1 = 601 subtractions",
       {{"method", kScs}, {"scene", 4}}},
      {"scs-torus",
       "SCS given a torus: the furthest front face is not where the ring begins (wrong)",
       {{"method", kScs}, {"scene", 3}},
       {},
       throughTheCut()},
      {"coincident",
       "A - B where B's top face lies in A's: z-fighting decides pixel by pixel",
       {{"method", kGoldfeather}, {"scene", 5}}},
      {"coincident-grown",
       "the same with B 0.01 taller: a clean pocket",
       {{"method", kGoldfeather}, {"scene", 6}}},
      {"layered-rack",
       "layered Goldfeather on the cube rack: 344 primitives, ids past 255 recorded modulo 255",
       {{"method", kLayered}, {"scene", 7}}},
      {"goldfeather-grid",
       "a box minus 25 spheres: 25 trimming primitives, more than the 8 stencil bits, flushed every 8",
       {{"method", kGoldfeather}, {"scene", 4}}},
      {"layered-grid", "the box minus 25 spheres, layered", {{"method", kLayered}, {"scene", 4}}},
  };
  info.passes = {"surface", "count",  "keep",      "far",      "layers",
                 "select",  "parity", "intersect", "subtract", "merge"};
  info.camera.target = {0.2f, 0.2f, 0.2f};
  info.camera.distance = 5.5f;
  info.camera.azimuthDeg = 30.0f;
  info.camera.elevationDeg = 25.0f;
  info.camera.farPlane = 30.0f;
  // A scene file is the scene: the options that pick the lesson's own scenes, and the demo's two
  // solids, have nothing to draw it with.
  info.refuseOptions = [](const OptionsChosen& o) -> std::string {
    if (!o.scene) return {};
    for (const char* own : {"scene", "op", "grid"})
      if (o.set(own))
        return std::string("--set ") + own + ": it picks among the lesson's own scenes; --scene " +
               o.scene->file.string() + " is the scene";
    if (o.value("method") == kTwoSolids)
      return "--scene: method 0 draws the demo's two solids; the scene's csg expression needs "
             "--set method=1, 2 or 3";
    return {};
  };
  return info;
}

}  // namespace

int main(int argc, char** argv) {
  return runSceneLesson(
      lessonInfo(), [](const Scene* fromFile) { return std::make_unique<Csg>(fromFile); }, argc, argv);
}