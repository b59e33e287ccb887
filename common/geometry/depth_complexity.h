// Depth complexity on the CPU, with no OpenGL: per pixel, how many surfaces the ray through the
// pixel's centre crosses inside the view volume. It is what a stencil that goes up by one per
// fragment counts with the depth test off (Kilgard, "Improving Shadows and Reflections via the
// Stencil Buffer", section 7), found independently of the rasterizer: an oracle for lesson 13.
#pragma once
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "geometry/shadow_oracle.h"

namespace stencil {

// Which faces are counted. A face is a front face when the ray meets the side its triangle winds
// counter-clockwise around (the side its normal points to), as GL culls with glFrontFace(GL_CCW)
// in an unmirrored view.
enum class FacesCounted { All, Front, Back };

// The count of every pixel of a size.x by size.y image seen through viewProjection (GL's clip
// conventions, clip z from -w to w; a far plane at infinity is fine), top row first like Image.
// A surface counts where the pixel centre's ray crosses it between the near and the far plane.
// Each object's mesh at its model matrix; casts and receives are ignored. A ray through an edge
// shared by two triangles crosses both (the rasterizer draws one): such pixels differ from their
// neighbours and are forgiven by compareCounts. Throws std::invalid_argument for an object given
// as a true sphere (OracleObject::sphere) or a mesh RayScene::add refuses.
std::vector<std::uint32_t> depthComplexity(const std::vector<OracleObject>& objects,
                                           const glm::mat4& viewProjection, glm::ivec2 size,
                                           FacesCounted faces = FacesCounted::All);

struct CountReport {
  std::size_t pixels = 0;                            // pixels compared
  std::size_t disagreements = 0;                     // pixels whose counts differ
  std::size_t onEdges = 0;                           // of which on an edge of the expected picture (forgiven)
  std::uint64_t expectedTotal = 0, actualTotal = 0;  // sums over every pixel
  bool passed() const { return disagreements == onEdges; }
};

// Compares two per-pixel counts of the same size (row order does not matter, as long as both
// agree). A pixel is on an edge when a pixel of its 3x3 neighbourhood has another expected count.
// Throws std::invalid_argument when either vector's size is not size.x * size.y.
CountReport compareCounts(const std::vector<std::uint32_t>& expected,
                          const std::vector<std::uint32_t>& actual, glm::ivec2 size);

}  // namespace stencil
