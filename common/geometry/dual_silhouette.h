// Dual-space silhouette extraction (Wallner, "Geometry of Real Time Shadows", section 4, after
// Hertzmann and Zorin's dual-space silhouettes for the eye): a face's supporting plane
// n.x = n.a is the point P = (n, -n.a) of 4D plane space, and a homogeneous light L faces it when
// P.L > 0. The light is the hyperplane P.L = 0 of that space, and an edge, whose two faces are
// two points, is a possible silhouette edge exactly when the segment between them crosses it.
// The segments go into a 4D tree once per caster (a "hextree": 16 children per cell, split at the
// cell's centre on all four axes); a query descends only into cells the light's hyperplane
// crosses.
//
// Faces, not vertex normals: Wallner's vertex normals give the smooth silhouette of the surface
// the mesh approximates, which does not lie on the mesh's edges. A shadow volume closed by the
// mesh's own faces needs the polygonal silhouette, the edges between faces that face the light
// and faces that do not; their planes are the points here.
//
// Exact: the tree only prunes, with a margin above float rounding, and every edge it reaches is
// decided by the facing test of SilhouetteCaster (shadow_volume.h), bit for bit the brute force's.
// The edges come back in the adjacency's order and direction, the same list as
// possibleSilhouetteEdges(const SilhouetteCaster&, light). Border edges (an open mesh) are on every
// silhouette; edges next to a degenerate face (no plane) are tested on every query.
#pragma once
#include <cstdint>
#include <glm/vec4.hpp>
#include <vector>

#include "geometry/shadow_volume.h"

namespace stencil {

class DualSilhouettes {
 public:
  // Builds the tree over a prepared caster (kept by reference: it must outlive this). maxLeaf:
  // a cell with more edges than this splits, down to maxDepth levels.
  explicit DualSilhouettes(const SilhouetteCaster& caster, std::size_t maxLeaf = 16, int maxDepth = 10);

  // The possible silhouette edges for a homogeneous light in the caster's space (w = 1 a point,
  // w = 0 the direction towards a directional light), as possibleSilhouetteEdges(caster, light) gives them.
  // `out` is replaced. The tree is descended only when the light differs from the last one
  // descended for, bit for bit in all four coordinates: a light given in the caster's object space
  // changes exactly when the light or the caster moves, so a still pair costs a copy of the last
  // answer, not a query (Wallner, section 4: the query reruns on relative motion only).
  void query(const glm::vec4& light, std::vector<SilhouetteEdge>& out) const;
  // The same answer, always by a descent of the tree (which becomes the answer query() reuses):
  // what a light that moved before every call costs, for benchmarks.
  void descend(const glm::vec4& light, std::vector<SilhouetteEdge>& out) const;

  // What the last call did: cells visited and edges tested exactly (both 0 when it reused the
  // previous answer, which `reused` says).
  struct QueryStats {
    std::size_t cellsVisited = 0, edgesTested = 0;
    bool reused = false;
  };
  const QueryStats& lastQuery() const { return stats_; }
  // How many calls descended the tree, and how many reused the previous answer, since it was built.
  std::size_t queriesRun() const { return queriesRun_; }
  std::size_t queriesReused() const { return queriesReused_; }
  std::size_t cellCount() const { return cells_.size(); }

 private:
  struct Cell {
    glm::vec4 lo, hi;            // the cell's box in plane space
    std::uint32_t firstChild;    // index of 16 consecutive children, or 0 for a leaf
    std::uint32_t first, count;  // its edges in edges_ (those that straddle its children's boxes)
  };
  void build(std::uint32_t cell, std::vector<std::uint32_t>& edges, int depth);
  bool faces(std::int32_t face, const glm::vec4& light) const;

  const SilhouetteCaster& caster_;
  std::vector<glm::vec4> planes_;      // per face: its unit plane (n, -n.a) / |.|; 0 if degenerate
  std::vector<Cell> cells_;            // cells_[0] is the root
  std::vector<std::uint32_t> edges_;   // edge indices, grouped by cell
  std::vector<std::uint32_t> always_;  // border edges and edges by a degenerate face
  float cornerScale_ = 0.0f;           // the largest |a| of a face's first corner, for the margin
  std::size_t maxLeaf_;
  int maxDepth_;
  mutable QueryStats stats_;
  mutable std::vector<std::uint32_t> found_;
  // The last light descended for and its answer: the cache query() keys on.
  mutable bool cached_ = false;
  mutable glm::vec4 cachedLight_{0.0f};
  mutable std::vector<SilhouetteEdge> cachedEdges_;
  mutable std::size_t queriesRun_ = 0, queriesReused_ = 0;
};

}  // namespace stencil
