#pragma once

// Vertex welding: merges vertices that share a position so that topology
// (edge adjacency, closedness, silhouettes) can be read off the index buffer.
// Shapes duplicate vertices at creases to carry several normals; welding is
// how shadow-volume code gets the connected surface back.
//
// Depends on: GLM, mesh (C++17).

#include <cstdint>
#include <vector>

#include "geometry/mesh.h"

namespace stencil {

struct WeldResult {
  Mesh mesh;
  // remap[old vertex] == new vertex; mesh.indices[k] == remap[input.indices[k]].
  std::vector<std::uint32_t> remap;
};

// Merges vertices whose positions compare equal with ==, so -0.0 and +0.0
// merge. Expected O(n) (hash map). Welded vertices keep the order of their
// first occurrence and that occurrence's position. Their normal is the
// renormalised sum of the merged normals (the first one if the sum cancels to
// zero); no normals in, no normals out. Triangles are kept even if welding
// made them degenerate, so counts stay comparable; buildEdgeAdjacency reports
// them. Throws std::invalid_argument for an invalid mesh or a non-finite
// position (NaN equals nothing, so it cannot be welded meaningfully).
WeldResult weldByPosition(const Mesh& mesh);

// Same, but a vertex merges into the first earlier kept vertex within
// `tolerance` (Euclidean distance). Greedy and order-dependent: chains of
// points each closer than `tolerance` to the next are not collapsed
// transitively. Uses a grid of cell size `tolerance` and checks the 27
// neighbouring cells, so it stays O(n) for sane input. tolerance == 0 is the
// exact weld; a negative, non-finite, or (for the coordinate range) too small
// tolerance throws std::invalid_argument.
WeldResult weldByPosition(const Mesh& mesh, float tolerance);

}  // namespace stencil
