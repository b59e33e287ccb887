// Lesson 14's automatic method (method 4): per product, the method that is right for it, with
// OpenCSG's economies and a few more (Kirsch and Döllner, "Rendering Techniques for
// Hardware-Accelerated Image-Based CSG", 2004; OpenCSG's Automatic setting):
//   - a product whose primitives are all convex (decided from each mesh, not from a bound the
//     user gives: geometry/shadow_volume.h's isConvex on the welded mesh) is drawn by SCS, its
//     subtractions applied in cycles of batches until one moves nothing (scsUntilUnchanged says
//     how the batches, the bound on the cycles and the redrawn batches follow from where the
//     primitives lie);
//   - a product with a concave primitive is drawn by layered Goldfeather, its layers counted by
//     one read of the stencil, each scissored to where it has pixels, kept where nearest and
//     merged once (layeredByLayerRects);
//   - every pass of a product is scissored to the window rectangle its intersected primitives
//     share, and the work buffer gets the primitive alone (its colour is the pass stepper's).
// None of this changes a pixel; each saves draws or llvmpipe's per-state-change copies.
#include <algorithm>
#include <iostream>
#include <limits>
#include <utility>

#include "csg_lesson.h"
#include "geometry/bounds.h"
#include "geometry/fast_shadows.h"
#include "geometry/shadow_volume.h"

namespace stencil::csg_lesson {

void Csg::automatic(Frame& f, const SumOfProducts& sop) {
  startCounts(f, sop,
              {"scs_products", "goldfeather_products", "cycles", "subtraction_passes", "clip_passes",
               "merge_passes"});
  workBuffer(f.size);
  mergeInputs();
  // The work buffer's colour is the pass stepper's picture alone: here only the primitives are
  // written, by a shader with nothing to light.
  const GLenum primitivesOnly[] = {GL_NONE, GL_COLOR_ATTACHMENT1};
  for (GLuint buffer : {nearest_, work_}) {  // (the two swap: keepNearest)
    glBindFramebuffer(GL_FRAMEBUFFER, buffer);
    glDrawBuffers(2, primitivesOnly);
  }
  glEnable(GL_SCISSOR_TEST);
  for (const CsgProduct& p : sop.products) {
    // A product's surface lies inside each of its intersected primitives: within all their window
    // rectangles. Every pass of the product, its merge too, is scissored to that.
    ScissorRect within{0, 0, f.size.x, f.size.y};
    for (int a : p.intersected) within = common(within, footprintOf(f, a).rect);
    if (within.width <= 0 || within.height <= 0) continue;  // off screen
    glScissor(within.x, within.y, within.width, within.height);
    const auto isConvex = [&](int i) { return convex_[static_cast<std::size_t>(i)]; };
    if (std::all_of(p.intersected.begin(), p.intersected.end(), isConvex) &&
        std::all_of(p.subtracted.begin(), p.subtracted.end(), isConvex)) {
      f.count("scs_products");
      scsUntilUnchanged(f, p, within);
    } else {
      f.count("goldfeather_products");
      layeredByLayerRects(f, p, within);
    }
  }
  unscissorAndDrawToBoth(f);
}

// SCS on one product of convex primitives (main.cpp's steps), the subtractions in cycles until
// one moves nothing, batched and bounded by where the subtracted primitives lie on screen and in
// the world (their footprints):
//   - a batch is subtracted primitives whose window rectangles do not overlap (taken greedily, in
//     the product's order): they share no pixel, so drawing them together is drawing them in
//     turn, with one change of state for all of them where each draw would change it twice
//     (llvmpipe copies 33 KB of state at each change);
//   - two subtracted primitives can meet along a pixel's ray only where their rectangles and
//     their world bounds overlap; a group is the primitives linked that way, and the order of
//     subtractions matters only within a group. The cycles run through the batches forwards and
//     backwards in turn, and the batch drawn last is not drawn again first (the surface it moved
//     lies on its back face, not behind it: it would move nothing), as SCS's sequence turns
//     (geometry/csg.h, subtractionSequence). The primitives on one pixel lie in different batches,
//     and n such cycles hold every ordering of n batches (the k-th of an ordering from the k-th
//     cycle, or from the end of the one before where the k-th cycle starts past it), so the cycles
//     stop at the largest group's size; where no two primitives meet, one cycle is the whole
//     answer and it needs no query;
//   - a batch that moved nothing, and meets no batch that moved something, since it was last
//     drawn would move nothing again: it is left out of the next cycle;
//   - a subtracted primitive whose batch never moved the surface is nowhere on it: not merged;
//     where the cycles waited on queries, the work buffer's primitives, read back after the last
//     wait, say which subtracted primitives the surface shows, and only those are merged.
void Csg::scsUntilUnchanged(Frame& f, const CsgProduct& p, const ScissorRect& within) {
  scsEnter(f, p, true);
  std::vector<int> shown;  // the subtracted primitives on screen (one off screen moves nothing)
  std::vector<Footprint> footprints;
  for (int s : p.subtracted) {
    const Footprint footprint = footprintOf(f, s);
    if (footprint.rect.width <= 0 || footprint.rect.height <= 0) continue;
    shown.push_back(s);
    footprints.push_back(footprint);
  }
  const std::size_t n = shown.size();
  std::vector<std::vector<int>> batches;
  std::vector<std::size_t> batchOf(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t b = 0;
    while (b < batches.size() && std::any_of(batches[b].begin(), batches[b].end(), [&](int j) {
             return overlap(footprints[i].rect, footprints[static_cast<std::size_t>(j)].rect);
           }))
      ++b;
    if (b == batches.size()) batches.emplace_back();
    batches[b].push_back(static_cast<int>(i));  // an index into shown until the groups are found
    batchOf[i] = b;
  }
  const std::size_t nb = batches.size();
  std::vector<std::size_t> group(n);  // union-find: each primitive's link towards its group
  for (std::size_t i = 0; i < n; ++i) group[i] = i;
  const auto groupOf = [&](std::size_t i) {
    while (group[i] != i) i = group[i] = group[group[i]];
    return i;
  };
  std::vector<std::vector<bool>> batchesMeet(nb, std::vector<bool>(nb, false));
  for (std::size_t b = 0; b < nb; ++b) batchesMeet[b][b] = true;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (meet(footprints[i], footprints[j])) {
        group[groupOf(i)] = groupOf(j);
        batchesMeet[batchOf[i]][batchOf[j]] = batchesMeet[batchOf[j]][batchOf[i]] = true;
      }
  std::vector<std::size_t> groupSize(n, 0);
  std::size_t cycles = 0;
  for (std::size_t i = 0; i < n; ++i) cycles = std::max(cycles, ++groupSize[groupOf(i)]);
  for (auto& batch : batches)
    for (int& i : batch) i = shown[static_cast<std::size_t>(i)];
  f.count("batches", nb);

  // Each wait for a cycle's result (a query, or the depth read back) drains llvmpipe's threads: the
  // rasterizers then idle while the next draws are set up. The waits can spare only the batches of
  // the cycles after the first, so where the bound holds few (cycles x batches at most 16: the
  // pipe's products hold 9, 9 and 16) the cycles run to it unwatched. Measured at 640x480,
  // unwatched: the pipe 15% faster, the 3D grid (27 cycles x 12 batches) five times slower.
  const bool waits = cycles > 1 && cycles * nb > 16;
  // Without queries whose result the frame can wait for (the browser's come after it) every batch
  // is merged, and the depth read back after each cycle says when one changed nothing: a cycle is a
  // function of the depth it starts from, so the next would change nothing either.
  std::vector<GLuint> queries(waits && f.features.samplesPassed ? nb : 0, 0);
  std::vector<float> depthBefore;
  std::vector<bool> moved(nb, true), onSurface(nb, queries.empty());
  std::vector<bool> shownThere;  // with queries, the primitives the work buffer names (primitivesIn)
  f.ownOcclusionQueries([&] {
    if (!queries.empty()) glGenQueries(static_cast<GLsizei>(nb), queries.data());
    glStencilMask(0xFF);
    std::size_t last = nb;  // the batch drawn last
    for (std::size_t cycle = 0; cycle < cycles; ++cycle) {
      f.count("cycles");
      std::vector<bool> drawn(nb, false);
      bool first = true;
      for (std::size_t step = 0; step < nb; ++step) {
        const std::size_t b = cycle % 2 ? nb - 1 - step : step;
        for (std::size_t c = 0; c < nb && !drawn[b]; ++c) drawn[b] = batchesMeet[b][c] && moved[c];
        // Drawn again straight after itself a batch moves nothing (a surface it moved lies on its back
        // face, not behind it): the cycles turn there.
        if (first && b == last) drawn[b] = false;
        if (!drawn[b]) continue;
        first = false;
        last = b;
        // Their back faces clear their marks, unless the far plane cuts some of them away.
        const bool clean =
            std::none_of(batches[b].begin(), batches[b].end(), [&](int s) { return reachesPastFar(f, s); });
        scsSubtract(f, batches[b], true, queries.empty() ? 0 : queries[b], clean);
        if (!clean) {
          for (std::size_t i = 0; i < n; ++i) {
            if (batchOf[i] != b) continue;
            const ScissorRect r = common(footprints[i].rect, within);
            glScissor(r.x, r.y, r.width, r.height);
            glClear(GL_STENCIL_BUFFER_BIT);  // the marks within its rectangle
          }
          glScissor(within.x, within.y, within.width, within.height);
        }
      }
      if (queries.empty()) {
        if (cycle + 1 == cycles) break;
        if (!waits) continue;
        std::vector<float> depth(static_cast<std::size_t>(within.width) * static_cast<std::size_t>(within.height));
        glReadPixels(within.x, within.y, within.width, within.height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
        if (depth == depthBefore) break;
        depthBefore = std::move(depth);
        continue;
      }
      bool any = false;
      for (std::size_t b = 0; b < nb; ++b) {
        GLuint64 samples = 0;
        if (drawn[b]) glGetQueryObjectui64v(queries[b], GL_QUERY_RESULT, &samples);
        moved[b] = samples > 0;
        onSurface[b] = onSurface[b] || moved[b];
        any = any || moved[b];
      }
      if (!any) break;
    }
    if (!queries.empty()) {
      // The last cycle's queries have waited for every subtraction: the read waits for nothing more.
      shownThere = primitivesIn(within);
      glDeleteQueries(static_cast<GLsizei>(nb), queries.data());
    }
  });
  f.pass("subtract");
  // Each subtraction left the stencil 0 within the product's rectangle (its back faces cleared their
  // marks, or the clear after it did), as scsEnter's clear did: the clip needs no clear of its own.
  clipByIntersection(f, p, true);
  f.pass("intersect");
  std::vector<bool> merged(models_.size(), false);  // in the product's order, as main.cpp merges
  for (std::size_t b = 0; b < nb; ++b)
    for (int s : batches[b]) merged[static_cast<std::size_t>(s)] = onSurface[b];
  if (!queries.empty()) {
    // The work buffer's primitives, read where the cycles had already waited, leave out of the merge
    // every target the surface does not show, where a batch that moved in some cycle may since have
    // been moved past everywhere (on the cube rack, most). The clip since only sent pixels to the far
    // plane: it shows no primitive the read did not find.
    for (int s : p.subtracted) merged[static_cast<std::size_t>(s)] = shownThere[static_cast<std::size_t>(s)];
  }
  std::vector<int> targets = p.intersected;
  for (int s : p.subtracted)
    if (merged[static_cast<std::size_t>(s)]) targets.push_back(s);
  mergeIntoFrame(f, p, targets);
}

// Per primitive, whether the work buffer's primitive texture names it within r (read back: a wait
// for the work buffer's passes, where any are still to run). Where a pass sent the surface to the
// far plane the texture may still name the primitive it held before: more than the surface shows,
// never less.
std::vector<bool> Csg::primitivesIn(const ScissorRect& r) const {
  std::vector<GLuint> ids(static_cast<std::size_t>(r.width) * static_cast<std::size_t>(r.height), 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, work_);
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(r.x, r.y, r.width, r.height, GL_RED_INTEGER, GL_UNSIGNED_INT, ids.data());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  std::vector<bool> there(models_.size(), false);
  for (GLuint id : ids)
    if (id > 0 && id <= there.size()) there[id - 1] = true;
  return there;
}

// Layered Goldfeather on one product with a concave primitive (main.cpp's steps), with these
// economies:
//   - the layers are counted by one read of the stencil (readCounts), which also says where each
//     layer has pixels: its passes are scissored to the rectangle that holds them, and a target
//     whose window rectangle holds none of them is left out of the layer's passes, as a target
//     and as a trimmer (it has no fragment on them; a subtracted primitive's parity there would be
//     0, as the product wants it; an intersected one's rectangle holds the product's, and every
//     layer's pixels);
//   - each layer's trimmed surface is kept where it is nearer than the layers before it
//     (keepNearest; the first layer's is kept whole, by swapping the work buffer with the nearest
//     layers' buffer), and the product is merged once, from that.
void Csg::layeredByLayerRects(Frame& f, const CsgProduct& p, const ScissorRect& within) {
  std::vector<int> targets = p.intersected;
  targets.insert(targets.end(), p.subtracted.begin(), p.subtracted.end());
  const bool queries = queriesWait(f);
  LayerCounts counts;
  const int k = queries ? 255 : targetDepthComplexity(f, p, targets, &counts);
  // Per target, the layers its rectangle has pixels of.
  std::vector<int> deepest;
  for (int x : targets) deepest.push_back(queries ? 255 : counts.largestWithin(footprintOf(f, x).rect));
  int layers = 0;
  for (int layer = 0; layer < k; ++layer) {
    std::vector<int> present;
    for (std::size_t i = 0; i < targets.size(); ++i)
      if (deepest[i] > layer) present.push_back(targets[i]);
    if (!queries) {
      const ScissorRect& r = counts.layers[static_cast<std::size_t>(layer)];
      glScissor(r.x, r.y, r.width, r.height);
    }
    if (!trimLayer(f, p, present, present, layer, true)) break;
    ++layers;
  }
  glScissor(within.x, within.y, within.width, within.height);
  if (layers == 0) clearNearest();  // no first layer took its place
  mergeIntoFrame(f, p, targets, true);
}

// The automatic method's step 3 of a layer: the work buffer's surface into nearest_, where it is
// nearer than the layers before it. The first layer's is the nearest yet wherever it has one, and
// far (the product's rectangle cleared by the count or the layer's own clear) wherever it has
// none: the two buffers swap, where a pass would copy it and change framebuffers twice (each
// change ends llvmpipe's batch of draws).
void Csg::keepNearest(Frame& f, int layer) {
  if (layer == 0) {
    std::swap(work_, nearest_);
    std::swap(workDepth_, nearestDepth_);
    std::swap(workColour_, nearestColour_);
    std::swap(workPrimitive_, nearestPrimitive_);
    f.pass("keep");
    return;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, nearest_);
  glDepthFunc(depth_.less);
  glDepthMask(GL_TRUE);
  glDisable(GL_STENCIL_TEST);  // (its stencil is no part of it)
  bindSurface(workDepth_, workPrimitive_);
  fullScreen(keep_);
  bindSurface(0, 0);
  glEnable(GL_STENCIL_TEST);
  f.pass("keep");
}

// Before a layered product's layers: nearest_'s depth back to the far plane (within the scissor).
void Csg::clearNearest() {
  glBindFramebuffer(GL_FRAMEBUFFER, nearest_);
  glDepthMask(GL_TRUE);
  glClear(GL_DEPTH_BUFFER_BIT);
}

// The stencil's counts within the scissor box (the product's rectangle), read back once.
Csg::LayerCounts Csg::readCounts() {
  LayerCounts c;
  GLint box[4] = {0, 0, 0, 0};
  glGetIntegerv(GL_SCISSOR_BOX, box);
  c.box = {box[0], box[1], box[2], box[3]};
  c.counts.assign(static_cast<std::size_t>(box[2]) * static_cast<std::size_t>(box[3]), 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(box[0], box[1], box[2], box[3], GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, c.counts.data());
  // One scan: per count, the corners of the pixels with it; the k-th layer's rectangle holds every
  // count above k.
  std::vector<glm::ivec2> low(256, glm::ivec2(std::numeric_limits<int>::max())), high(256, glm::ivec2(-1));
  for (int y = 0; y < c.box.height; ++y)
    for (int x = 0; x < c.box.width; ++x) {
      const int n = c.at(x, y);
      c.largest = std::max(c.largest, n);
      low[static_cast<std::size_t>(n)] = glm::min(low[static_cast<std::size_t>(n)], glm::ivec2(x, y));
      high[static_cast<std::size_t>(n)] = glm::max(high[static_cast<std::size_t>(n)], glm::ivec2(x, y));
    }
  c.layers.resize(static_cast<std::size_t>(c.largest));
  for (int k = c.largest - 1; k >= 0; --k) {
    const auto above = static_cast<std::size_t>(k + 1);
    if (k + 1 < c.largest) {  // every count above k + 1 too
      low[above] = glm::min(low[above], low[above + 1]);
      high[above] = glm::max(high[above], high[above + 1]);
    }
    c.layers[static_cast<std::size_t>(k)] = {c.box.x + low[above].x, c.box.y + low[above].y,
                                             high[above].x - low[above].x + 1, high[above].y - low[above].y + 1};
  }
  return c;
}

int Csg::LayerCounts::largestWithin(const ScissorRect& r) const {
  const ScissorRect within = common(r, box);
  int largestThere = 0;
  for (int y = within.y - box.y; y < within.y - box.y + within.height; ++y)
    for (int x = within.x - box.x; x < within.x - box.x + within.width; ++x)
      largestThere = std::max(largestThere, at(x, y));
  return largestThere;
}

int Csg::LayerCounts::at(int x, int y) const {
  const std::size_t row = static_cast<std::size_t>(y) * static_cast<std::size_t>(box.width);
  return counts[row + static_cast<std::size_t>(x)];
}

// Primitive i's footprint this frame: its object box at its model, as a world box, the world
// sphere around its mesh's own sphere, and the window rectangle (GL's origin bottom left) that
// holds the box's corners projected, a pixel wider each way; the whole window where a corner lies
// behind the eye, empty where the box is off screen.
Csg::Footprint Csg::footprintOf(const Frame& f, int i) const {
  const auto& [low, high] = boxes_[static_cast<std::size_t>(i)];
  const glm::mat4& model = models_[static_cast<std::size_t>(i)];
  const glm::mat4 toClip = f.projection * view_ * model;
  Footprint footprint;
  glm::vec2 lowNdc(std::numeric_limits<float>::max()), highNdc(-std::numeric_limits<float>::max());
  bool behind = false;
  for (int c = 0; c < 8; ++c) {
    const glm::vec4 corner((c & 1) ? high.x : low.x, (c & 2) ? high.y : low.y, (c & 4) ? high.z : low.z, 1.0f);
    footprint.box.extend(glm::vec3(model * corner));
    const glm::vec4 clip = toClip * corner;
    behind = behind || clip.w <= 0.0f;
    if (clip.w > 0.0f) lowNdc = glm::min(lowNdc, glm::vec2(clip) / clip.w), highNdc = glm::max(highNdc, glm::vec2(clip) / clip.w);
  }
  const BoundingSphere& sphere = spheres_[static_cast<std::size_t>(i)];
  const glm::mat3 linear(model);
  footprint.sphere.centre = glm::vec3(model * glm::vec4(sphere.centre, 1.0f));
  footprint.sphere.radius =
      sphere.radius * std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
  if (behind) {
    footprint.rect = {0, 0, f.size.x, f.size.y};
    return footprint;
  }
  const glm::vec2 size(f.size);
  const glm::ivec2 first = glm::max(glm::ivec2(glm::floor((lowNdc * 0.5f + 0.5f) * size)) - 1, glm::ivec2(0));
  const glm::ivec2 last = glm::min(glm::ivec2(glm::ceil((highNdc * 0.5f + 0.5f) * size)) + 1, f.size);
  if (last.x > first.x && last.y > first.y) footprint.rect = {first.x, first.y, last.x - first.x, last.y - first.y};
  return footprint;
}

ScissorRect Csg::common(const ScissorRect& a, const ScissorRect& b) {
  const int x = std::max(a.x, b.x), y = std::max(a.y, b.y);
  return {x, y, std::max(0, std::min(a.x + a.width, b.x + b.width) - x),
          std::max(0, std::min(a.y + a.height, b.y + b.height) - y)};
}

bool Csg::overlap(const ScissorRect& a, const ScissorRect& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

// Whether two primitives can share a point that a pixel's ray passes: their rectangles, world
// boxes and world spheres all overlap.
bool Csg::meet(const Footprint& a, const Footprint& b) {
  return overlap(a.rect, b.rect) && glm::all(glm::lessThanEqual(a.box.min, b.box.max)) &&
         glm::all(glm::lessThanEqual(b.box.min, a.box.max)) &&
         glm::distance(a.sphere.centre, b.sphere.centre) <= a.sphere.radius + b.sphere.radius;
}

// Primitive i's bounding sphere in world space: its object-space box's corners at its model.
BoundingSphere Csg::worldSphereOf(int i) const {
  const auto& [low, high] = boxes_[static_cast<std::size_t>(i)];
  const glm::mat4& model = models_[static_cast<std::size_t>(i)];
  std::vector<glm::vec3> corners;
  for (int c = 0; c < 8; ++c)
    corners.emplace_back(model * glm::vec4((c & 1) ? high.x : low.x, (c & 2) ? high.y : low.y,
                                           (c & 4) ? high.z : low.z, 1.0f));
  return boundingSphereOf(corners);
}

// Whether primitive i's bounding sphere reaches past Frame::projection's far plane (which then cuts
// its back faces). With reversed depth the far plane is at infinity and this answer is only
// conservative: a clear too many, never one too few.
bool Csg::reachesPastFar(const Frame& f, int i) const {
  const BoundingSphere sphere = worldSphereOf(i);
  const glm::vec3 centre = glm::vec3(view_ * glm::vec4(sphere.centre, 1.0f));
  // Its farthest point from the eye along the view axis, projected.
  const glm::vec4 clip = f.projection * glm::vec4(centre.x, centre.y, centre.z - sphere.radius, 1.0f);
  return clip.w > 0.0f && clip.z > clip.w;
}

}  // namespace stencil::csg_lesson
