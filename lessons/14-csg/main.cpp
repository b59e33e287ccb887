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
// per other primitive a parity bit (INVERT where its faces lie behind: z-fail), then the pixels whose
// bits say "outside an intersected one" or "inside a subtracted one" pushed to the far plane.
// What is left is drawn into the frame where the fragment is that depth, the depth test keeping
// the nearest of all: products merge by depth. A concave target has several faces along a ray;
// the stencil EQUAL k selects the k-th fragment drawn at each pixel (INCR on every fragment), so
// a convexity bound c tries c layers of each target: O(n^2 c) passes for a product of n. Layered
// Goldfeather selects the k-th fragment of all the product's target faces at once, k up to the
// largest depth complexity of those faces (lesson 13's count): k(1 + n) passes. An occlusion
// query that finds a layer empty stops either early. INCR stops at 255, which may mean more: refused.
//
// SCS (Stewart, Leach and John), for convex primitives only: the intersection is entered at the
// furthest of the intersected front faces (if every intersected back face lies behind it), and a
// subtracted primitive moves the surface to its back face where the surface lies inside it; the
// subtracted primitives are applied in a sequence that holds every ordering of them, since they
// may lie along a ray in any order (geometry/csg.h, subtractionSequence).
//
// Goldfeather and SCS build each product's surface in a work buffer of their own, its depth and
// the primitive each depth came from (the merge draws that primitive there, at exactly that
// depth, as OpenCSG records IDs); its colour is painted for the pass stepper only (the selected
// layer lit, trimmed pixels the background), so stepping through the passes shows the work
// buffer's colour, depth and stencil at each step. Depth is reversed and floating-point where the
// driver has clip control (lesson 15), every comparison flipped with it.
// Reading order: render, the two solids, Goldfeather, layered Goldfeather (its depth complexity), SCS;
// beside it automatic.cpp (per product SCS or layered Goldfeather), drawing.cpp (the work buffer and
// draws), classroom.cpp (scenes, options, variants), refusals.cpp (what no method draws), oracle.cpp.

#include <algorithm>
#include <string>
#include <vector>

#include "csg_lesson.h"

namespace stencil::csg_lesson {

void Csg::render(Frame& f) {
  const int method = f.option("method");
  const CsgScene scene = sceneFor(f, fromFile_);
  const CsgTree tree = prepare(scene, f);  // the models and the view (from the eye, far out)
  const SumOfProducts sop = normalize(tree);
  refuseCuts(f, scene, sop);  // the near plane cutting the result (no method draws its cap)
  beginFrame(f, method == kTwoSolids);  // the depth mapping (reversed float depth where it can be)

  if (method == kTwoSolids)
    twoSolidsMethod(f, scene, f.option("op"));
  else if (method == kScs)
    scs(f, sop);
  else if (method == kAutomatic)
    automatic(f, sop);
  else
    goldfeather(f, sop, method == kLayered);
  endFrame(f);  // GL's defaults again
  if (f.on("oracle")) checkAgainstRayCast(f, scene, tree, method);
}

// ---- two convex solids (the demo) ---------------------------------------------------------------

// One surface of the pair: `faces` (GL_FRONT or GL_BACK) of primitive x where it lies inside
// (wantInside) or outside solid s, tagged with `kept` in the stencil. Pixels already tagged
// belong to the nearer surface of the pair and are left alone.
void Csg::keepSurface(Frame& f, int x, GLenum faces, int s, bool wantInside, GLuint kept, bool trim) {
  const GLuint tagged = kKeptA | kKeptB;
  // 1. The surface's nearest face into the depth buffer, where no surface is kept yet.
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // depth only
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(depth_.less);  // the nearest of x's chosen faces
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

void Csg::twoSolidsMethod(Frame& f, const CsgScene&, int op) {
  const bool trim = f.on("stencil");
  constexpr int a = 0, b = 1;
  if (op == kUnion) {
    // Both solids, the nearer surface wins; the stencil only records whose surface it is.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(depth_.less);
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

// ---- Goldfeather --------------------------------------------------------------------------------

// One product's surface, one target at a time (or, layered, all its targets at once), into
// the work buffer's depth, trimmed there, merged into the frame.
void Csg::goldfeather(Frame& f, const SumOfProducts& sop, bool layered) {
  startCounts(f, sop, {"select_passes", "parity_passes", "far_passes", "merge_passes", "layers"}, true);
  workBuffer(f.size);
  mergeInputs();
  for (const CsgProduct& product : sop.products) {
    std::vector<int> targets = product.intersected;
    targets.insert(targets.end(), product.subtracted.begin(), product.subtracted.end());
    if (layered) {
      const int k = queriesWait(f) ? 255 : targetDepthComplexity(f, product, targets);
      for (int layer = 0; layer < k; ++layer)
        if (!trimLayer(f, product, targets, targets, layer)) break;
    } else {
      for (int x : targets) {
        std::vector<int> others;
        for (int y : targets)
          if (y != x) others.push_back(y);
        // The target's convexity: 1 for a convex mesh, else the most of its target faces any
        // pixel's ray crosses (lesson 13's count of them, this frame), never a guess; a bound
        // given with --set convexity overrides it (to show what too low a bound does).
        const int c = f.option("convexity") > 0 ? f.option("convexity")
                      : convex_[static_cast<std::size_t>(x)] ? 1
                                                             : targetDepthComplexity(f, product, {x});
        for (int layer = 0; layer < c; ++layer)
          if (!trimLayer(f, product, {x}, others, layer)) break;
      }
    }
  }
  // The frame again: a layer found empty (queries) ends in the work buffer.
  glBindFramebuffer(GL_FRAMEBUFFER, f.framebuffer());
}

// Layer `layer` of the targets' faces, trimmed by `trimmers` and merged into the frame (with
// `automatic`, the automatic method's: the work buffer gets the primitive alone, and the layer is
// kept where nearest, to be merged once). Returns false when an occlusion query found the layer
// empty (with the queries option): no later layer has a fragment either.
bool Csg::trimLayer(Frame& f, const CsgProduct& p, const std::vector<int>& targets,
                    const std::vector<int>& trimmers, int layer, bool automatic) {
  glBindFramebuffer(GL_FRAMEBUFFER, work_);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilMask(0xFF);
  clearWork();
  // 1. Select: the layer-th fragment drawn at each pixel. Every fragment INCRs the stencil, and only
  // the one that finds it EQUAL to layer writes its depth and its primitive (and its colour: no part
  // of the method, it shows the surface to the pass stepper).
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);  // in draw order, not depth order: every fragment is some layer
  glDepthMask(GL_TRUE);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, layer, 0xFF);
  glStencilOp(GL_INCR, GL_INCR, GL_INCR);  // each fragment counts, passing or not
  const auto select = [&] { drawTargets(p, targets, automatic ? Paint::Primitive : Paint::Selected); };
  std::uint64_t selected = 1;
  if (queriesWait(f))
    selected = samplesPassed(f, select);
  else
    select();
  f.count("select_passes");
  f.pass("select");
  if (selected == 0) return false;
  if (layer == 254) refuseDeepCount(f, p, targets);  // a 255th fragment (queries): 255 or more layers
  f.count("layers");  // a layer with fragments, trimmed and merged

  // 2. Parity: one stencil bit per trimming primitive, INVERT where its faces lie behind the
  // selected surface (z-fail parity, as OpenCSG 1.8 counts: a closed primitive has as many faces
  // along a ray in front of a point as behind it, modulo 2, and those behind survive where the
  // near plane cuts the primitive or the eye is inside it; the far plane must not cut it). A
  // face on the surface is not behind it: a surface counts as inside the intersected primitive it
  // belongs to and outside the subtracted one. After 8 bits, or the last, the
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
      glDepthFunc(further());
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

  // 3. Merge: the targets drawn into the frame where they are the trimmed surface (or, the
  // automatic method, the surface kept where it is the nearest layer's yet).
  if (automatic)
    keepNearest(f, layer);
  else
    mergeIntoFrame(f, p, targets);
  return true;
}

// Merge: the product's surface into the frame where it is nearer than the other products' (the
// depth test keeps the nearest of all), then its targets drawn lit there. First a full-screen pass
// (14-csg/resolve.frag) writes the work buffer's depth into the frame's depth where it is nearer,
// and the primitive recorded beside it into the frame's stencil (its index modulo 255, + 1: the
// oracle reads it). Then each target is drawn with the depth test EQUAL and the stencil test EQUAL
// to its own tag, writing colour only: the same triangle drawn again lands on the same depth
// (gl_Position is invariant), and another target's face crossing the surface there, however close
// in depth, carries another tag (OpenCSG records the primitive's ID the same way); the shader
// still compares the recorded primitive, for two primitives 255 apart. Nothing is written but
// colour, so the tests run before the lighting (early_fragment_tests in 14-csg/merge.frag).
// Without stencil export (ARB_shader_stencil_export; WebGL 2) the merge is one pass: each target
// drawn with its depth and tag written where the shader finds it is the surface (no early tests
// then: the shader decides before the writes). Both give the same picture.
void Csg::mergeIntoFrame(Frame& f, const CsgProduct& p, const std::vector<int>& targets, bool fromNearest) {
  glBindFramebuffer(GL_FRAMEBUFFER, f.framebuffer());
  bindSurface(fromNearest ? nearestDepth_ : workDepth_, fromNearest ? nearestPrimitive_ : workPrimitive_);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glDepthFunc(depth_.less);
  glDepthMask(GL_TRUE);
  glStencilMask(0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  clearFrame();  // the first merge of the frame
  const bool twoPasses = hasFeature(f.features, Feature::StencilExport);
  if (twoPasses) {
    // 1. The surface's depth where it is the nearest yet, its primitive in the stencil.
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);  // the shader's value (gl_FragStencilRefARB)
    fullScreen(resolve_);
    // 2. Each target lit where the frame holds its tag at exactly its depth.
    glDepthFunc(GL_EQUAL);
    glDepthMask(GL_FALSE);
    glStencilMask(0);
  }
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  for (int x : targets) {
    glStencilFunc(twoPasses ? GL_EQUAL : GL_ALWAYS, x % 255 + 1, 0xFF);
    drawTargets(p, {x}, Paint::Merged);
  }
  glDepthMask(GL_TRUE);
  glStencilMask(0xFF);
  bindSurface(0, 0);
  f.count("merge_passes");
  f.pass("merge");
}

// Lesson 13's count on the targets' faces (all the product's, layered; one concave target's, method
// 1): INCR on every fragment, the depth test off; the largest count, found by bisection with stencil
// LESS and occlusion queries, is the number of layers the layered method needs.
int Csg::targetDepthComplexity(Frame& f, const CsgProduct& p, const std::vector<int>& targets,
                               LayerCounts* counts) {
  glBindFramebuffer(GL_FRAMEBUFFER, work_);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilMask(0xFF);
  clearWork();
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // the count alone
  glDisable(GL_DEPTH_TEST);                             // every fragment counts
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  drawTargets(p, targets, Paint::Depth);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  int low = 0, high = 255;  // the largest count lies in [low, high]
  LayerCounts read;  // where no query can be waited for within the frame (the browser's)
  if (!counts && !f.features.samplesPassed) counts = &read;
  if (counts) {  // read once, for the bisection's 8 queries
    *counts = readCounts();
    low = high = counts->largest;
  }
  while (low < high) {
    const int middle = (low + high) / 2;
    glStencilFunc(GL_LESS, middle, 0xFF);  // passes where middle < count
    if (samplesPassed(f, [&] { drawQuad(glm::vec4(0.0f), 0.0f); }) > 0)
      low = middle + 1;
    else
      high = middle;
  }
  if (low == 255) refuseDeepCount(f, p, targets);  // INCR stops at 255: 255 or more, and layers lost
  glEnable(GL_DEPTH_TEST);
  f.count("layers_counted", static_cast<std::uint64_t>(low));
  f.pass("layers");
  return low;
}

// ---- SCS -----------------------------------------------------------------------------------------

// Per product, in the work buffer: the intersection of its intersected primitives as the
// furthest front face that no back face lies in front of (convex primitives: that is where the
// ray enters all of them), then each subtracted primitive in the order of the subtraction
// sequence moves the surface to its back face where the surface lies inside it, then the
// intersection clips again; the surface is merged into the frame as Goldfeather's is.
void Csg::scs(Frame& f, const SumOfProducts& sop) {
  startCounts(f, sop, {"sequence_length", "subtraction_passes", "clip_passes", "merge_passes"});
  workBuffer(f.size);
  mergeInputs();
  for (const CsgProduct& p : sop.products) {
    scsEnter(f, p);
    // 2. The subtraction sequence.
    const std::vector<int> order = subtractionSequence(static_cast<int>(p.subtracted.size()));
    f.count("sequence_length", order.size());
    for (int i : order) scsSubtract(f, {p.subtracted[static_cast<std::size_t>(i)]});
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

// SCS's step 1, in the work buffer: the intersected primitives' front faces, the furthest kept,
// clipped to where the ray is inside them all. With `automatic` (its economies) the work buffer
// gets the primitive alone (here and in scsSubtract), and this clip is left to the one after the
// subtractions: a surface behind an intersected primitive's back face, or where one has none,
// stays so as the subtractions move it back, and that clip sends it to the far plane as this one
// would have (and there no subtraction would have moved it).
void Csg::scsEnter(Frame& f, const CsgProduct& p, bool automatic) {
  glBindFramebuffer(GL_FRAMEBUFFER, work_);
  // The work buffer's colour follows the surface as it moves (no part of the method: the
  // pass stepper's picture of it).
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilMask(0xFF);
  glClearDepth(nearest());  // the furthest front face wins: start at the near plane
  clearWork();
  glClearDepth(depth_.farthest);
  // No primitive yet: where no front face is drawn the depth stays at the near plane, and the
  // merge must not take it for a surface.
  const GLuint none[4] = {0, 0, 0, 0};
  glClearBufferuiv(GL_COLOR, 1, none);
  // 1. The intersected primitives' front faces, the furthest kept: where the ray has entered
  // them all, if it is inside them all there.
  glDepthFunc(further());
  glDepthMask(GL_TRUE);
  glStencilFunc(GL_ALWAYS, 0, 0);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glCullFace(GL_BACK);
  for (int a : p.intersected) automatic ? drawPrimitive(a) : drawSelected(a);
  if (!automatic) clipByIntersection(f, p);
  f.pass("intersect");
}

// SCS's step 2 for one subtracted primitive s: where the surface lies inside s (s's back face
// behind it, its front face not: in front, or cut away by the near plane when the eye is inside
// s), the surface moves back to s's back face. The front face is tested behind (z-fail) so that a
// front face the near plane removed reads as in front. Several primitives that share no pixel
// (the automatic method's batches) are the same as one after the other, and are drawn together.
// A non-zero `query` counts the fragments that moved (GL_SAMPLES_PASSED around the move alone).
// With `clean`, the stencil is left as found (0): s's back faces cover every pixel its front
// faces marked (a closed convex solid whose back faces the far plane does not cut: a front face
// beyond the near plane has its back face beyond it too), and each mark they meet goes back to
// 0; the next subtraction needs no clear.
void Csg::scsSubtract(Frame& f, const std::vector<int>& batch, bool automatic, GLuint query, bool clean) {
  glStencilMask(0xFF);
  if (!clean) glClear(GL_STENCIL_BUFFER_BIT);
  glDepthFunc(furtherOrEqual());  // s's front face behind the surface, or on it: not inside s
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glStencilFunc(GL_ALWAYS, 1, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glCullFace(GL_BACK);
  for (int s : batch) drawDepth(s);
  glDepthFunc(further());  // elsewhere, its back face behind it: the surface is inside s
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);  // it moves to that back face
  glStencilFunc(GL_EQUAL, 0, 0xFF);
  if (clean)
    glStencilOp(GL_ZERO, GL_KEEP, GL_KEEP);  // a mark fails the test and goes back to 0
  else
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glCullFace(GL_FRONT);
  if (query) glBeginQuery(GL_SAMPLES_PASSED, query);
  for (int s : batch) automatic ? drawPrimitive(s) : drawSelected(s);
  if (query) glEndQuery(GL_SAMPLES_PASSED);
  f.count("subtraction_passes", 2);
}

// Counts the intersected primitives whose back face lies behind the surface (or on it) and sends
// every pixel where that is not all of them to the far plane: the surface lies outside one, or a
// primitive does not cover the pixel at all (no back face to count; checking for a back face in
// front would miss that one). 255 at a time (INCR stops there). `cleared`: the stencil is 0 already.
void Csg::clipByIntersection(Frame& f, const CsgProduct& p, bool cleared) {
  for (std::size_t first = 0; first < p.intersected.size(); first += 255) {
    const std::size_t n = std::min<std::size_t>(p.intersected.size() - first, 255);
    glStencilMask(0xFF);
    if (!cleared || first > 0) glClear(GL_STENCIL_BUFFER_BIT);
    glDepthFunc(furtherOrEqual());  // the back face behind the surface: the surface is before it leaves
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glStencilFunc(GL_ALWAYS, 0, 0);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    glCullFace(GL_FRONT);
    for (std::size_t i = first; i < first + n; ++i) drawDepth(p.intersected[i]);
    glDepthFunc(GL_ALWAYS);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0);
    glStencilFunc(GL_NOTEQUAL, static_cast<GLint>(n), 0xFF);
    farQuad();
    glStencilMask(0xFF);
  }
  f.count("clip_passes");
}

}  // namespace stencil::csg_lesson

int main(int argc, char** argv) {
  using namespace stencil;
  return runSceneLesson(
      csg_lesson::lessonInfo(), [](const Scene* fromFile) { return std::make_unique<csg_lesson::Csg>(fromFile); },
      argc, argv);
}
