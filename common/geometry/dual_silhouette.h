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
#include <utility>
#include <vector>

#include "geometry/shadow_volume.h"

namespace stencil {

namespace detail {
// The last light descended for and its answer: the cache query() keys on (Wallner, section 4:
// the query reruns on relative motion only).
struct LastSilhouette {
  bool valid = false;
  glm::vec4 light{0.0f};
  std::vector<SilhouetteEdge> edges;
  std::size_t run = 0, reused = 0;  // calls that descended, calls that reused `edges`
  // Copies the answer into `out` and counts a reuse when `light` is the last one bit for bit.
  bool reuse(const glm::vec4& light, std::vector<SilhouetteEdge>& out);
  void keep(const glm::vec4& light, const std::vector<SilhouetteEdge>& out);
};
}  // namespace detail

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
  std::size_t queriesRun() const { return last_.run; }
  std::size_t queriesReused() const { return last_.reused; }
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
  mutable detail::LastSilhouette last_;
};

// ---- a bounding volume hierarchy over the dual edges ------------------------------------------
//
// The same answer, output-sensitive. Sander, Gu, Gortler, Hoppe and Snyder ("Silhouette
// Clipping", SIGGRAPH 2000, its silhouette extraction) search a tree of edge clusters and skip a
// cluster when all the faces of its edges face the viewpoint, or all face away, which a pair of
// anchored cones bounds. Here a cluster is bounded in Wallner's plane space instead: the 4D box of
// its edges' segments (both faces' unit planes), which the light's hyperplane P.L = 0 misses
// exactly when P.L keeps one sign over it, that is when no face of the cluster can disagree with
// another about the light. Where the hextree keeps a segment that crosses a cell's split in that
// cell, tested by every query that reaches it, here every edge lies in a leaf whose box is fitted
// to it and its neighbours (split at the median of the segments' centres along the widest axis),
// so a query reaches only the leaves along the silhouette and their ancestors.
//
// Layout for a descent: four children per node, their boxes stored axis by axis and tested
// together (SSE); nodes in depth-first order, visited a level at a time so that a level's loads
// overlap; a leaf's edges consecutive, their two faces' unit planes stored four edges to a group,
// component by component (32 bytes an edge, four edges tested at once), so that a leaf is one run
// of memory. The caster's arrays are read only for a face too close to edge-on for its plane to
// decide (then by the brute force's own test, as DualSilhouettes does). Exact on the same terms as
// DualSilhouettes: the boxes and planes only prune or decide with a margin above float rounding;
// the list is possibleSilhouetteEdges(caster, light), order and direction included.
class DualEdgeBvh {
 public:
  // Builds the hierarchy over a prepared caster (kept by reference: it must outlive this). maxLeaf:
  // the most edges a leaf holds, clamped to 1..255. Build cost O(E log E) for E edges; memory
  // 36 bytes an edge and 192 a node (about one node per 18 edges with the default leaves). Throws
  // std::length_error for 2^31 edges or more.
  explicit DualEdgeBvh(const SilhouetteCaster& caster, std::size_t maxLeaf = 8);

  // As DualSilhouettes::query and ::descend: the possible silhouette edges for a homogeneous light
  // in the caster's space, `out` replaced; query() reuses the last answer for the same light bit for
  // bit, descend() always descends.
  void query(const glm::vec4& light, std::vector<SilhouetteEdge>& out) const;
  void descend(const glm::vec4& light, std::vector<SilhouetteEdge>& out) const;

  // What the last call did: nodes whose children's boxes were tested, edges whose planes were
  // tested (those of the leaves reached, and the edges always tested), and how many of them needed
  // the brute force's test (a face within the margin of edge-on). All 0 when it reused the answer.
  struct QueryStats {
    std::size_t nodesVisited = 0, edgesTested = 0, exactTests = 0;
    bool reused = false;
  };
  const QueryStats& lastQuery() const { return stats_; }
  std::size_t queriesRun() const { return last_.run; }
  std::size_t queriesReused() const { return last_.reused; }
  std::size_t nodeCount() const { return nodes_.size(); }

 private:
  struct alignas(64) Node {     // three cache lines
    float lo[4][4], hi[4][4];  // [axis][child]: the children's boxes in plane space
    std::uint32_t first[4];    // a child node's index, or a leaf's first edge in leafEdges_
    std::uint32_t count[4];    // 0 for a child node, else the leaf's number of edges
    std::uint32_t used = 0;    // one bit per child present
  };
  struct Item;
  void build(std::uint32_t node, Item* begin, Item* end);
  static void prefetch(const Node* node);
  void prefetchPlanes(const std::pair<std::uint32_t, std::uint32_t>& leaf) const;

  const SilhouetteCaster& caster_;
  std::vector<Node> nodes_;                 // nodes_[0] is the root
  // The edges in leaf order, four to a group, their faces' unit planes stored component by
  // component: planes[0..3][lane] face0's x, y, z, w; planes[4..7][lane] face1's.
  struct alignas(16) PlaneGroup {
    float planes[8][4];
  };
  std::vector<PlaneGroup> leafPlanes_;
  std::vector<std::uint32_t> leafEdges_;    // per edge in leaf order: its index in the caster
  std::vector<std::uint32_t> always_;       // border edges and edges by a degenerate face
  float cornerScale_ = 0.0f;                // the largest |a| of a face's first corner, for the margin
  std::size_t maxLeaf_;
  mutable QueryStats stats_;
  mutable std::vector<std::uint32_t> found_, sortSpare_;  // edge << 1 | whether face0 faces the light
  mutable std::vector<std::uint32_t> level_, next_;  // the descent's nodes, one level at a time
  mutable std::vector<std::pair<std::uint32_t, std::uint32_t>> leaves_;  // leaves reached: first, count
  mutable detail::LastSilhouette last_;
};

}  // namespace stencil
