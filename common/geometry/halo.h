// What lesson 11 (the magic halo) measures on its pictures, and the smoothed normals its
// extrusion needs. GL-free: masks are one byte per pixel, rows top down, size.x * size.y.
#pragma once
#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

#include "geometry/mesh.h"

namespace stencil {

// The Euclidean distance from each pixel centre to the nearest pixel whose seed is non-zero, in
// pixels (0 on a seed); +infinity everywhere when there is no seed. Exact (Felzenszwalb and
// Huttenlocher's lower envelope of parabolas, once along the columns and once along the rows).
// Throws std::invalid_argument when seeds.size() is not size.x * size.y.
std::vector<float> distanceTransform(const std::vector<std::uint8_t>& seeds, glm::ivec2 size);

// A halo measured on one picture.
struct HaloMeasure {
  std::size_t objectPixels = 0;   // the haloed object's visible pixels
  std::size_t haloPixels = 0;     // blended at least once and not the object's
  std::size_t coveredPixels = 0;  // the object's pixels blended at least once: the halo over the object
  std::size_t multiPixels = 0;    // blended more than once
  std::size_t blends = 0;         // every blend counted: the sum of the counts
  // The width along the object's outline: from each outline pixel (an object pixel with a
  // 4-neighbour that is not the object's), a ray along the outline's outward normal (the mean
  // direction towards the non-object pixels within 2 pixels) leaves the object, crosses the halo,
  // and the width is how far it ran in the halo before it met a pixel that is neither. So a halo k
  // pixels wide measures about k, and no halo 0. A ray that crosses the halo into the object again
  // has crossed a gap the halo filled (between the legs, under an arm), and so has one that reaches
  // a halo pixel nearer to another part of the object than to where the ray began (a pixel more
  // than 1.5 pixels nearer, by the distance transform): that outline pixel counts as filled, not
  // sampled. Rays that meet a blocked pixel or the picture's border are not sampled either.
  std::size_t outlinePixels = 0;  // sampled
  std::size_t filledPixels = 0;   // outline pixels facing a gap the halo filled
  double widthMean = 0.0, widthMin = 0.0, widthMax = 0.0;
};

// object: non-zero where the haloed object shows. blends: how many times the halo was blended into
// each pixel. blocked: non-zero where something else shows that the halo may rightly not cover
// (another object, an occluder); such pixels are neither outside nor halo, and the outline beside
// them is not sampled. May be empty. Throws std::invalid_argument for masks of the wrong size.
HaloMeasure measureHalo(const std::vector<std::uint8_t>& object, const std::vector<std::uint8_t>& blends,
                        const std::vector<std::uint8_t>& blocked, glm::ivec2 size);

// The mesh with each normal replaced by the normalised sum of the normals of every vertex at the
// same position (bit for bit): a crease's split vertices then move together when pushed along their
// normals, so the pushed surface has no cracks. Throws std::invalid_argument for a mesh without
// normals (validateMesh's checks first).
Mesh smoothNormals(const Mesh& mesh);

}  // namespace stencil
