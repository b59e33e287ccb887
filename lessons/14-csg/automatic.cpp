// Lesson 14's automatic method (method 4): per product, the method that is right for it, with two
// of OpenCSG's economies (Kirsch and Döllner, "Rendering Techniques for Hardware-Accelerated
// Image-Based CSG", 2004; OpenCSG's Automatic setting):
//   - a product whose primitives are all convex (decided from each mesh, not from a bound the
//     user gives: geometry/shadow_volume.h's isConvex on the welded mesh) is drawn by SCS, its
//     subtractions applied in cycles, each cycle every subtracted primitive once, an occlusion
//     query counting the fragments each cycle moves; the first cycle that moves none ends it.
//     A surface that no subtracted primitive moves lies in none of them: it is final. n cycles
//     hold every ordering of n primitives (the k-th of an ordering from the k-th cycle), so the
//     cycles never do more than the full sequence needs;
//   - a product with a concave primitive is drawn by layered Goldfeather (its layers counted);
//   - each subtracted primitive's passes are scissored to the window rectangle of its bounding
//     sphere (lightScissor, lesson 16's): a primitive changes no pixel outside it, and one wholly
//     off screen is skipped; and the stencil is not cleared before each subtraction: s's back
//     faces set its marks back to 0 as they move the surface.
#include <algorithm>

#include "csg_lesson.h"
#include "geometry/bounds.h"
#include "geometry/fast_shadows.h"
#include "geometry/shadow_volume.h"

namespace stencil::csg_lesson {

void Csg::automatic(Frame& f, const SumOfProducts& sop) {
  f.count("products", sop.products.size());
  f.count("literals", sop.literals());
  for (const char* name : {"scs_products", "goldfeather_products", "cycles", "subtraction_passes", "clip_passes",
                           "merge_passes"})
    f.count(name, 0);
  workBuffer(f.size);
  mergeInputs();
  for (const CsgProduct& p : sop.products) {
    const auto isConvex = [&](int i) { return convex_[static_cast<std::size_t>(i)]; };
    if (std::all_of(p.intersected.begin(), p.intersected.end(), isConvex) &&
        std::all_of(p.subtracted.begin(), p.subtracted.end(), isConvex)) {
      f.count("scs_products");
      scsUntilUnchanged(f, p);
    } else {
      f.count("goldfeather_products");
      SumOfProducts one;
      one.products.push_back(p);
      goldfeather(f, one, true);
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, f.framebuffer());
}

// SCS on one product of convex primitives (main.cpp's steps), the subtractions in cycles until
// one moves nothing.
void Csg::scsUntilUnchanged(Frame& f, const CsgProduct& p) {
  scsEnter(f, p);
  const std::size_t n = p.subtracted.size();
  std::vector<GLuint> queries(n, 0);
  f.ownOcclusionQueries([&] {
    glGenQueries(static_cast<GLsizei>(n), queries.data());
    glStencilMask(0xFF);
    glClear(GL_STENCIL_BUFFER_BIT);  // scsEnter's clip left its counts (all of them: no scissor yet)
    glEnable(GL_SCISSOR_TEST);
    for (std::size_t cycle = 0; cycle < n; ++cycle) {
      f.count("cycles");
      std::vector<bool> drawn(n, false);
      for (std::size_t i = 0; i < n; ++i) {
        const int s = p.subtracted[i];
        if (!scissorTo(f, s)) continue;  // off screen: it moves nothing
        // Its back faces clear its marks, unless the far plane cuts some of them away.
        const bool clean = !reachesPastFar(f, s);
        scsSubtract(f, s, queries[i], clean);
        if (!clean) {
          glStencilMask(0xFF);
          glClear(GL_STENCIL_BUFFER_BIT);  // within the scissor: s's marks
        }
        drawn[i] = true;
      }
      GLuint64 moved = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (drawn[i]) {
          GLuint64 samples = 0;
          glGetQueryObjectui64v(queries[i], GL_QUERY_RESULT, &samples);
          moved += samples;
        }
      if (moved == 0) break;
    }
    glDisable(GL_SCISSOR_TEST);
    glDeleteQueries(static_cast<GLsizei>(n), queries.data());
  });
  f.pass("subtract");
  clipByIntersection(f, p);
  f.pass("intersect");
  std::vector<int> targets = p.intersected;
  targets.insert(targets.end(), p.subtracted.begin(), p.subtracted.end());
  mergeIntoFrame(f, p, targets);
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

// The scissor rectangle of primitive i's bounding sphere; false when it is wholly off screen.
bool Csg::scissorTo(const Frame& f, int i) const {
  const BoundingSphere sphere = worldSphereOf(i);
  const ScissorRect r = lightScissor(sphere.centre, sphere.radius, f.projection * f.view, f.size);
  if (r.width <= 0 || r.height <= 0) return false;
  glScissor(r.x, r.y, r.width, r.height);
  return true;
}

// Whether primitive i's bounding sphere reaches past Frame::projection's far plane (which then cuts
// its back faces). With reversed depth the far plane is at infinity and this answer is only
// conservative: a clear too many, never one too few.
bool Csg::reachesPastFar(const Frame& f, int i) const {
  const BoundingSphere sphere = worldSphereOf(i);
  const glm::vec3 centre = glm::vec3(f.view * glm::vec4(sphere.centre, 1.0f));
  // Its farthest point from the eye along the view axis, projected.
  const glm::vec4 clip = f.projection * glm::vec4(centre.x, centre.y, centre.z - sphere.radius, 1.0f);
  return clip.w > 0.0f && clip.z > clip.w;
}

}  // namespace stencil::csg_lesson
