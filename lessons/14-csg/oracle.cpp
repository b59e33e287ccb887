// Lesson 14's test hook: the frame's depth and the primitive its stencil records, against the CSG
// ray cast (geometry/csg.h), reported as --stats counts oracle_*; a pixel wrong off the edges fails
// the run (exit 1).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "csg_lesson.h"

namespace stencil::csg_lesson {

// The frame's depth and the primitive its stencil records, against the CSG ray cast.
void Csg::checkAgainstRayCast(Frame& f, const CsgScene& scene, const CsgTree& tree, int method) const {
  // Cast from the eye, whichever frame the picture was drawn from: every coordinate its distance
  // from the eye, the models moved in double and rounded once, the view its rotation alone.
  const glm::dmat4 toEye = glm::translate(glm::dmat4(1.0), glm::dvec3(origin_) - glm::dvec3(f.eye));
  std::vector<CsgPrimitive> primitives;
  for (std::size_t i = 0; i < scene.primitives.size(); ++i)
    primitives.push_back({&scene.primitives[i].mesh, glm::mat4(toEye * glm::dmat4(models_[i]))});
  const glm::mat4 viewProjection = f.projection * glm::mat4(glm::mat3(f.view));
  CsgImage expected = rayCastCsg(primitives, tree, viewProjection, f.size);
  // 8 stencil bits record the primitive modulo 255 (0 is none): past 254 primitives the ray
  // cast's are compared modulo 255 too.
  if (method != kTwoSolids)
    for (std::size_t i = 0; i < expected.primitive.size(); ++i) {
      if (expected.primitive[i] >= 0) expected.primitive[i] %= 255;
      for (int& s : expected.sharedWith[i]) s %= 255;
    }
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
    depth[i] = f.reversedDepth ? 1.0f - depthRows[row] : depthRows[row];  // the ray cast's mapping
    const std::uint8_t s = stencilRows[row];
    if (method == kTwoSolids)
      primitive[i] = (s & kKeptA) ? 0 : (s & kKeptB) ? 1 : kNoSurface;
    else
      primitive[i] = s == 0 ? kNoSurface : s - 1;
  }
  // Edges from the geometry: what can be seen changes within the pixel's square, grown by the
  // rasterizer's vertex snapping (2^-GL_SUBPIXEL_BITS pixels).
  GLint subpixelBits = 4;  // GL's least
  glGetIntegerv(GL_SUBPIXEL_BITS, &subpixelBits);
  const float snap = std::ldexp(1.0f, -std::max(subpixelBits, 4));
  const std::vector<bool> edges = csgEdgePixels(primitives, viewProjection, f.size, snap);
  // Depth in window units of GL's mapping: a few steps of 2^-24 (the 24-bit buffer's rounding, or
  // a reversed float depth's taken from 1; the ray cast's float rounding near 1; the rasterizer's
  // interpolation), plus the surface's slope over the snapping.
  const CsgReport r = compareCsg(expected, depth, primitive, edges, 4.0f * std::ldexp(1.0f, -24), snap);
  f.count("oracle_pixels", r.pixels);
  f.count("oracle_primitive_disagreements", r.primitiveDisagreements);
  f.count("oracle_depth_disagreements", r.depthDisagreements);
  f.count("oracle_on_edges", r.onEdges);
  f.count("oracle_edge_pixels", r.edgePixels);
  f.count("oracle_largest_depth_error_1e9", static_cast<std::uint64_t>(r.largestDepthError * 1e9f));
  if (!r.passed())
    f.checkFailed("oracle: " + std::to_string(r.primitiveDisagreements + r.depthDisagreements - r.onEdges) +
                  " pixels off the edges show another primitive or depth than the CSG ray cast");
}

}  // namespace stencil::csg_lesson
