#pragma once

// Edge adjacency of an indexed triangle list: the input to shadow-volume
// silhouette extraction (an edge is on the silhouette when exactly one of its
// two faces faces the light) and the check that a mesh is closed before
// z-fail capping is trusted. Indices must refer to welded vertices
// (weldByPosition), otherwise seams show up as border edges.
//
// Depends on: the standard library only (C++17).

#include <cstddef>
#include <cstdint>
#include <vector>

namespace stencil {

// face0 walks v0 -> v1; face1 walks v1 -> v0, or is -1 for a border edge.
// Faces are triangle numbers (index / 3). For the edges listed as
// inconsistent or non-manifold in EdgeAdjacency, face1 may walk v0 -> v1 too
// (see there). So face1 == -1 exactly when the edge is a border edge.
struct Edge {
  std::uint32_t v0, v1;
  std::int32_t face0;
  std::int32_t face1;
};

struct AdjacencyReport {
  std::size_t borderEdges = 0;          // exactly one face
  std::size_t nonManifoldEdges = 0;     // three or more faces
  std::size_t inconsistentEdges = 0;    // two faces walking it the same way
  std::size_t degenerateTriangles = 0;  // two equal indices; skipped

  // Every edge has exactly two faces walking it in opposite directions:
  // closed, two-manifold and consistently oriented, which is what shadow
  // volumes need. Degenerate triangles are skipped and do not break this.
  bool closedManifold() const;
};

// Categories are disjoint: a non-manifold edge is not also counted as
// inconsistent or border.
//
// Non-manifold edges keep two of their faces in `edges` (face0 = first face
// seen, face1 = first later face walking the other way, else the second face
// seen); the extra faces are not stored. Such a mesh is unfit for shadow
// volumes anyway: check report.closedManifold() before using silhouettes.
struct EdgeAdjacency {
  std::vector<Edge> edges;  // in order of first appearance in the index list
  AdjacencyReport report;
  std::vector<std::uint32_t> borderEdgeIndices;          // into edges
  std::vector<std::uint32_t> nonManifoldEdgeIndices;     // into edges
  std::vector<std::uint32_t> inconsistentEdgeIndices;    // into edges
  std::vector<std::uint32_t> degenerateTriangleIndices;  // triangle numbers
};

// Expected O(n): a hash map keyed by the ordered vertex pair. The check is
// purely combinatorial; a zero-area triangle with three distinct indices is
// not degenerate here. Throws std::invalid_argument if indices.size() is not a
// multiple of 3, an index is >= vertexCount, or there are more triangles than
// an int32 face number can name.
EdgeAdjacency buildEdgeAdjacency(const std::vector<std::uint32_t>& indices, std::size_t vertexCount);

}  // namespace stencil
