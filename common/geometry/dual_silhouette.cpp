#include "geometry/dual_silhouette.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>
#include <utility>

#ifdef __SSE2__
#include <xmmintrin.h>
#endif

namespace stencil {

namespace {

glm::vec4 minOf(const glm::vec4& a, const glm::vec4& b) {
  return glm::min(a, b);
}
glm::vec4 maxOf(const glm::vec4& a, const glm::vec4& b) {
  return glm::max(a, b);
}

// Every face's unit plane (n, -n.a) / |(n, -n.a)| from the caster's own normal n and first corner
// a, rounded once from double; 0 for a face without a plane (zero normal). cornerScale: the
// largest |a|, which the pruning margin scales with.
std::vector<glm::vec4> unitPlanes(const SilhouetteCaster& caster, float& cornerScale) {
  std::vector<glm::vec4> planes(caster.faceCount());
  cornerScale = 0.0f;
  for (std::size_t f = 0; f < planes.size(); ++f) {
    const glm::dvec3 n(caster.nx[f], caster.ny[f], caster.nz[f]), a(caster.ax[f], caster.ay[f], caster.az[f]);
    const glm::dvec4 p(n, -glm::dot(n, a));
    const double length = glm::length(p);
    planes[f] = length > 0.0 && std::isfinite(length) && glm::length(n) > 0.0 ? glm::vec4(p / length)
                                                                              : glm::vec4(0.0f);
    cornerScale = std::max(cornerScale, static_cast<float>(glm::length(a)));
  }
  return planes;
}

// Tested on every query, not in the tree: a border edge (an open mesh's, on every silhouette) and
// an edge next to a face without a plane.
bool alwaysTested(const SilhouetteCaster& caster, const std::vector<glm::vec4>& planes,
                  const SilhouetteCaster::EdgeFaces& ef) {
  return static_cast<std::size_t>(ef.face1) == caster.faceCount() || planes[ef.face0] == glm::vec4(0.0f) ||
         planes[ef.face1] == glm::vec4(0.0f);
}

// P.L of a unit plane decides the brute force's facing test when it is further from 0 than this.
// With u = 2^-24: the brute force computes F = n.(l - w a) (l = L.xyz, w = L.w) within
// 5u |n| (|l|_1 + |w| |a|_1) (three roundings to a term, two to the sum), and F = |(n, -n.a)| P.L
// with |(n, -n.a)| >= |n|, so P.L beyond 5u (|l|_1 + sqrt(3) |w| |a|) fixes F's sign, and the
// float's. The unit planes are rounded once (u per component, |P_i| <= 1) and P.L, or its least
// and greatest value over a box, is summed in float: 5u |L|_1 more. 4e-6 (67u) covers the sum of
// both with room to spare. Infinite or NaN for a light that is: then nothing is pruned or decided.
float pruningMargin(const glm::vec4& light, float cornerScale) {
  return 4e-6f * (std::abs(light.x) + std::abs(light.y) + std::abs(light.z) +
                  std::abs(light.w) * (1.0f + cornerScale));
}

// The brute force's own test and arithmetic (shadow_volume.cpp's facing pass).
bool facesLight(const SilhouetteCaster& c, std::int32_t f, const glm::vec4& light) {
  const auto t = static_cast<std::size_t>(f);
  const float x = c.nx[t] * (light.x - light.w * c.ax[t]);
  const float y = c.ny[t] * (light.y - light.w * c.ay[t]);
  const float z = c.nz[t] * (light.z - light.w * c.az[t]);
  return (x + y) + z > 0.0f;
}

// The same four floats, bit for bit (so -0 differs from 0 and a NaN from itself: never reused).
bool sameBits(const glm::vec4& a, const glm::vec4& b) {
  return std::memcmp(&a, &b, sizeof a) == 0 && a == b;
}

}  // namespace

namespace detail {

bool LastSilhouette::reuse(const glm::vec4& l, std::vector<SilhouetteEdge>& out) {
  if (!valid || !sameBits(l, light)) return false;
  ++reused;
  out = edges;
  return true;
}

void LastSilhouette::keep(const glm::vec4& l, const std::vector<SilhouetteEdge>& out) {
  ++run;
  valid = true;
  light = l;
  edges = out;
}

}  // namespace detail

DualSilhouettes::DualSilhouettes(const SilhouetteCaster& caster, std::size_t maxLeaf, int maxDepth)
    : caster_(caster), maxLeaf_(std::max<std::size_t>(1, maxLeaf)), maxDepth_(maxDepth) {
  planes_ = unitPlanes(caster, cornerScale_);
  std::vector<std::uint32_t> inTree;
  glm::vec4 lo(1.0f), hi(-1.0f);
  for (std::uint32_t e = 0; e < caster.edgeFaces.size(); ++e) {
    const SilhouetteCaster::EdgeFaces& ef = caster.edgeFaces[e];
    if (alwaysTested(caster, planes_, ef)) {
      always_.push_back(e);
      continue;
    }
    inTree.push_back(e);
    lo = minOf(lo, minOf(planes_[ef.face0], planes_[ef.face1]));
    hi = maxOf(hi, maxOf(planes_[ef.face0], planes_[ef.face1]));
  }
  cells_.push_back({lo, hi, 0, 0, 0});
  build(0, inTree, 0);
}

void DualSilhouettes::build(std::uint32_t cell, std::vector<std::uint32_t>& edges, int depth) {
  const glm::vec4 lo = cells_[cell].lo, hi = cells_[cell].hi, mid = 0.5f * (lo + hi);
  if (edges.size() <= maxLeaf_ || depth >= maxDepth_) {
    cells_[cell].first = static_cast<std::uint32_t>(edges_.size());
    cells_[cell].count = static_cast<std::uint32_t>(edges.size());
    edges_.insert(edges_.end(), edges.begin(), edges.end());
    return;
  }
  // A point's child: one bit per axis, set when it lies on the upper side of the centre.
  const auto child = [&](const glm::vec4& p) {
    return (p.x >= mid.x ? 1 : 0) | (p.y >= mid.y ? 2 : 0) | (p.z >= mid.z ? 4 : 0) | (p.w >= mid.w ? 8 : 0);
  };
  std::vector<std::uint32_t> kept, parts[16];
  for (std::uint32_t e : edges) {
    const SilhouetteCaster::EdgeFaces& ef = caster_.edgeFaces[e];
    const int c0 = child(planes_[ef.face0]), c1 = child(planes_[ef.face1]);
    (c0 == c1 ? parts[c0] : kept).push_back(e);  // a segment across children stays here
  }
  edges.clear();
  edges.shrink_to_fit();
  cells_[cell].first = static_cast<std::uint32_t>(edges_.size());
  cells_[cell].count = static_cast<std::uint32_t>(kept.size());
  edges_.insert(edges_.end(), kept.begin(), kept.end());
  const auto firstChild = static_cast<std::uint32_t>(cells_.size());
  cells_[cell].firstChild = firstChild;
  for (int c = 0; c < 16; ++c) {
    const glm::vec4 clo((c & 1) ? mid.x : lo.x, (c & 2) ? mid.y : lo.y, (c & 4) ? mid.z : lo.z,
                        (c & 8) ? mid.w : lo.w);
    const glm::vec4 chi((c & 1) ? hi.x : mid.x, (c & 2) ? hi.y : mid.y, (c & 4) ? hi.z : mid.z,
                        (c & 8) ? hi.w : mid.w);
    cells_.push_back({clo, chi, 0, 0, 0});
  }
  for (int c = 0; c < 16; ++c) build(firstChild + static_cast<std::uint32_t>(c), parts[c], depth + 1);
}

void DualSilhouettes::query(const glm::vec4& light, std::vector<SilhouetteEdge>& out) const {
  if (last_.reuse(light, out)) {
    stats_ = {0, 0, true};
    return;
  }
  descend(light, out);
}

void DualSilhouettes::descend(const glm::vec4& light, std::vector<SilhouetteEdge>& out) const {
  stats_ = {};
  out.clear();
  found_.clear();
  // The hyperplane P.L = 0 misses a box when P.L keeps one sign over it by more than the margin:
  // only then is a cell left out.
  const float margin = pruningMargin(light, cornerScale_);
  const auto test = [&](std::uint32_t e) {
    ++stats_.edgesTested;
    const SilhouetteCaster::EdgeFaces& ef = caster_.edgeFaces[e];
    const bool lit0 = facesLight(caster_, ef.face0, light);
    const bool border = static_cast<std::size_t>(ef.face1) == caster_.faceCount();
    if (border || lit0 != facesLight(caster_, ef.face1, light)) found_.push_back(e);
  };
  for (std::uint32_t e : always_) test(e);
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const Cell& c = cells_[stack.back()];
    stack.pop_back();
    float lo = 0.0f, hi = 0.0f;  // P.L over the box
    for (int i = 0; i < 4; ++i) {
      const float a = c.lo[i] * light[i], b = c.hi[i] * light[i];
      lo += std::min(a, b);
      hi += std::max(a, b);
    }
    if (lo > margin || hi < -margin) continue;
    ++stats_.cellsVisited;
    for (std::uint32_t k = c.first; k < c.first + c.count; ++k) test(edges_[k]);
    if (c.firstChild != 0)
      for (std::uint32_t k = 0; k < 16; ++k) stack.push_back(c.firstChild + k);
  }
  std::sort(found_.begin(), found_.end());
  for (std::uint32_t e : found_) {
    const SilhouetteCaster::EdgeFaces& ef = caster_.edgeFaces[e];
    const SilhouetteEdge& ends = caster_.edgeEnds[e];
    out.push_back(facesLight(caster_, ef.face0, light) ? ends : SilhouetteEdge{ends.v1, ends.v0});
  }
  last_.keep(light, out);
}

// ---- DualEdgeBvh ------------------------------------------------------------------------------

// One edge while building: its segment's box in plane space (face0's and face1's unit planes).
struct DualEdgeBvh::Item {
  glm::vec4 lo, hi;
  std::uint32_t edge;
  // Twice the centre on one axis (only compared), without glm's switch on the index.
  float centre(int axis) const { return (&lo.x)[axis] + (&hi.x)[axis]; }
};

namespace {

// A hint that `bytes` from `p` will be read soon (no effect on the result).
void prefetchBytes(const void* p, std::size_t bytes) {
#if defined(__GNUC__)
  const auto* c = static_cast<const char*>(p);
  for (std::size_t offset = 0; offset < bytes; offset += 64) __builtin_prefetch(c + offset);
#else
  (void)p;
  (void)bytes;
#endif
}

// Sorts 32-bit keys ascending: a least-significant-digit radix sort, three passes of 11 bits, for
// the few thousand edges a silhouette has (a comparison sort's branches cost more there).
void sortEdges(std::vector<std::uint32_t>& keys, std::vector<std::uint32_t>& spare) {
  if (keys.size() < 256) {
    std::sort(keys.begin(), keys.end());
    return;
  }
  spare.resize(keys.size());
  std::uint32_t counts[3][2048] = {};
  for (std::uint32_t k : keys) {
    ++counts[0][k & 2047u];
    ++counts[1][(k >> 11) & 2047u];
    ++counts[2][k >> 22];
  }
  for (int pass = 0; pass < 3; ++pass) {
    std::uint32_t sum = 0;
    for (std::uint32_t& c : counts[pass]) sum += std::exchange(c, sum);
    const int shift = 11 * pass;
    for (std::uint32_t k : keys) spare[counts[pass][(k >> shift) & 2047u]++] = k;
    keys.swap(spare);
  }
}

}  // namespace

void DualEdgeBvh::prefetch(const Node* node) {
  prefetchBytes(node, sizeof(Node));
}

void DualEdgeBvh::prefetchPlanes(const std::pair<std::uint32_t, std::uint32_t>& leaf) const {
  const std::size_t first = leaf.first / 4, last = (leaf.first + leaf.second - 1) / 4;
  prefetchBytes(leafPlanes_.data() + first, (last + 1 - first) * sizeof(PlaneGroup));
}

DualEdgeBvh::DualEdgeBvh(const SilhouetteCaster& caster, std::size_t maxLeaf)
    : caster_(caster), maxLeaf_(std::clamp<std::size_t>(maxLeaf, 1, 255)) {
  if (caster.edgeFaces.size() >= (std::size_t{1} << 31))
    throw std::length_error("DualEdgeBvh: " + std::to_string(caster.edgeFaces.size()) +
                            " edges, the most is 2^31 - 1");
  const std::vector<glm::vec4> planes = unitPlanes(caster, cornerScale_);
  std::vector<Item> items;
  items.reserve(caster.edgeFaces.size());
  for (std::uint32_t e = 0; e < caster.edgeFaces.size(); ++e) {
    const SilhouetteCaster::EdgeFaces& ef = caster.edgeFaces[e];
    if (alwaysTested(caster, planes, ef))
      always_.push_back(e);
    else
      items.push_back({minOf(planes[ef.face0], planes[ef.face1]), maxOf(planes[ef.face0], planes[ef.face1]), e});
  }
  // A node per four leaves or so, and every edge in one leaf.
  nodes_.reserve(1 + items.size() / std::max<std::size_t>(1, maxLeaf_ / 2) / 3);
  leafEdges_.reserve(items.size());
  nodes_.push_back({});
  if (!items.empty()) build(0, items.data(), items.data() + items.size());
  // The leaves' planes, in leaf order: the only face data a descent reads.
  leafPlanes_.assign((leafEdges_.size() + 3) / 4, PlaneGroup{});
  for (std::size_t k = 0; k < leafEdges_.size(); ++k) {
    const SilhouetteCaster::EdgeFaces& ef = caster.edgeFaces[leafEdges_[k]];
    PlaneGroup& group = leafPlanes_[k / 4];
    for (int c = 0; c < 4; ++c) {
      group.planes[c][k % 4] = planes[ef.face0][c];
      group.planes[4 + c][k % 4] = planes[ef.face1][c];
    }
  }
}

void DualEdgeBvh::build(std::uint32_t node, Item* begin, Item* end) {
  // Up to four parts: split the largest part with more than maxLeaf_ edges at the median of the
  // segments' centres along the axis where those centres spread widest, until there are four.
  std::pair<Item*, Item*> parts[4] = {{begin, end}};
  int count = 1;
  while (count < 4) {
    int widest = -1;
    for (int k = 0; k < count; ++k)
      if (static_cast<std::size_t>(parts[k].second - parts[k].first) > maxLeaf_ &&
          (widest < 0 || parts[k].second - parts[k].first > parts[widest].second - parts[widest].first))
        widest = k;
    if (widest < 0) break;
    auto [b, e] = parts[widest];
    glm::vec4 lo(b->lo + b->hi), hi = lo;
    for (const Item* i = b; i != e; ++i) {
      lo = glm::min(lo, i->lo + i->hi);
      hi = glm::max(hi, i->lo + i->hi);
    }
    int axis = 0;
    for (int a = 1; a < 4; ++a)
      if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
    Item* mid = b + (e - b) / 2;
    std::nth_element(b, mid, e, [axis](const Item& x, const Item& y) { return x.centre(axis) < y.centre(axis); });
    parts[widest] = {b, mid};
    parts[count++] = {mid, e};
  }
  // The children in the order of their edges (the splits keep each part contiguous).
  std::sort(parts, parts + count, [](const auto& x, const auto& y) { return x.first < y.first; });
  for (int k = 0; k < count; ++k) {
    auto [b, e] = parts[k];
    glm::vec4 lo = b->lo, hi = b->hi;
    for (const Item* i = b; i != e; ++i) {
      lo = glm::min(lo, i->lo);
      hi = glm::max(hi, i->hi);
    }
    for (int a = 0; a < 4; ++a) {
      nodes_[node].lo[a][k] = lo[a];
      nodes_[node].hi[a][k] = hi[a];
    }
    nodes_[node].used |= 1u << k;
    const auto size = static_cast<std::size_t>(e - b);
    if (size <= maxLeaf_) {
      nodes_[node].first[k] = static_cast<std::uint32_t>(leafEdges_.size());
      nodes_[node].count[k] = static_cast<std::uint32_t>(size);
      for (const Item* i = b; i != e; ++i) leafEdges_.push_back(i->edge);
    } else {
      const auto child = static_cast<std::uint32_t>(nodes_.size());
      nodes_.push_back({});  // depth first: a child's subtree follows it
      nodes_[node].first[k] = child;
      nodes_[node].count[k] = 0;
      build(child, b, e);
    }
  }
}

void DualEdgeBvh::query(const glm::vec4& light, std::vector<SilhouetteEdge>& out) const {
  if (last_.reuse(light, out)) {
    stats_ = {0, 0, 0, true};
    return;
  }
  descend(light, out);
}

void DualEdgeBvh::descend(const glm::vec4& light, std::vector<SilhouetteEdge>& out) const {
  stats_ = {};
  out.clear();
  found_.clear();
  const float margin = pruningMargin(light, cornerScale_);
  // face0 and face1 of an edge: decided by the unit plane when P.L is beyond the margin, else by
  // the brute force's test. An edge goes in when they disagree, with face0's flag for its direction.
  // (The caster's edge record is read only for such a face: most edges come here decided.)
  const auto decide = [&](std::uint32_t e, float d0, float d1) {
    const auto side = [&](float d, bool second) {
      if (d > margin) return true;
      if (d < -margin) return false;
      ++stats_.exactTests;
      const SilhouetteCaster::EdgeFaces& ef = caster_.edgeFaces[e];
      return facesLight(caster_, second ? ef.face1 : ef.face0, light);
    };
    const bool lit0 = side(d0, false);
    if (lit0 != side(d1, true)) found_.push_back(e << 1 | (lit0 ? 1u : 0u));
  };
  for (std::uint32_t e : always_) {
    ++stats_.edgesTested;
    const SilhouetteCaster::EdgeFaces& ef = caster_.edgeFaces[e];
    const bool lit0 = facesLight(caster_, ef.face0, light);
    const bool border = static_cast<std::size_t>(ef.face1) == caster_.faceCount();
    if (border || lit0 != facesLight(caster_, ef.face1, light)) found_.push_back(e << 1 | (lit0 ? 1u : 0u));
  }
  // Breadth first: the nodes of one level are independent of each other, so their boxes' loads
  // overlap (and are prefetched when found); the leaves reached are tested after the descent, a few
  // leaves' planes prefetched ahead.
  level_.clear();
  leaves_.clear();
  if (!nodes_.empty() && nodes_[0].used != 0) level_.push_back(0);
#ifdef __SSE2__
  const __m128 L[4] = {_mm_set1_ps(light.x), _mm_set1_ps(light.y), _mm_set1_ps(light.z), _mm_set1_ps(light.w)};
  const __m128 above = _mm_set1_ps(margin), below = _mm_set1_ps(-margin);
#endif
  while (!level_.empty()) {
    next_.clear();
    for (std::uint32_t index : level_) {
      const Node& n = nodes_[index];
      ++stats_.nodesVisited;
      // P.L over each child's box, four children at once: its least and greatest value. A child is
      // left out when the whole box is beyond the margin on one side (never for a NaN).
#ifdef __SSE2__
      __m128 least = _mm_setzero_ps(), most = _mm_setzero_ps();
      for (int a = 0; a < 4; ++a) {
        const __m128 x = _mm_mul_ps(_mm_load_ps(n.lo[a]), L[a]), y = _mm_mul_ps(_mm_load_ps(n.hi[a]), L[a]);
        least = _mm_add_ps(least, _mm_min_ps(x, y));
        most = _mm_add_ps(most, _mm_max_ps(x, y));
      }
      const auto missed = static_cast<std::uint32_t>(
          _mm_movemask_ps(_mm_or_ps(_mm_cmpgt_ps(least, above), _mm_cmplt_ps(most, below))));
#else
      std::uint32_t missed = 0;
      for (int k = 0; k < 4; ++k) {
        float least = 0.0f, most = 0.0f;
        for (int a = 0; a < 4; ++a) {
          const float x = n.lo[a][k] * light[a], y = n.hi[a][k] * light[a];
          least += std::min(x, y);
          most += std::max(x, y);
        }
        if (least > margin || most < -margin) missed |= 1u << k;
      }
#endif
      for (std::uint32_t hit = n.used & ~missed; hit != 0; hit &= hit - 1) {
        const int k = std::countr_zero(hit);
        if (n.count[k] != 0) {
          leaves_.push_back({n.first[k], n.count[k]});
        } else {
          next_.push_back(n.first[k]);
          prefetch(&nodes_[n.first[k]]);
        }
      }
    }
    std::swap(level_, next_);
  }
  constexpr std::size_t ahead = 8;  // leaves
  for (std::size_t i = 0; i < std::min(ahead, leaves_.size()); ++i) prefetchPlanes(leaves_[i]);
  for (std::size_t i = 0; i < leaves_.size(); ++i) {
    if (i + ahead < leaves_.size()) prefetchPlanes(leaves_[i + ahead]);
    const auto [first, count] = leaves_[i];
    stats_.edgesTested += count;
    // Four edges at a time, the groups that hold the leaf's: both faces beyond the margin on one
    // side, not on the silhouette (most edges of a leaf). The others (lanes of this leaf only) are
    // looked at one by one.
    for (std::uint32_t g = first / 4; g <= (first + count - 1) / 4; ++g) {
      const PlaneGroup& group = leafPlanes_[g];
      const std::uint32_t from = std::max(first, 4 * g) - 4 * g, to = std::min(first + count, 4 * g + 4) - 4 * g;
      const std::uint32_t lanes = ((1u << to) - 1u) & ~((1u << from) - 1u);
      alignas(16) float d0[4], d1[4];
#ifdef __SSE2__
      const auto dot = [&](int c) {  // ((x + y) + z) + w, four lanes
        const __m128 xy = _mm_add_ps(_mm_mul_ps(_mm_load_ps(group.planes[c]), L[0]),
                                     _mm_mul_ps(_mm_load_ps(group.planes[c + 1]), L[1]));
        return _mm_add_ps(_mm_add_ps(xy, _mm_mul_ps(_mm_load_ps(group.planes[c + 2]), L[2])),
                          _mm_mul_ps(_mm_load_ps(group.planes[c + 3]), L[3]));
      };
      const __m128 a = dot(0), b = dot(4);
      _mm_store_ps(d0, a);
      _mm_store_ps(d1, b);
      const __m128 settled = _mm_or_ps(_mm_and_ps(_mm_cmpgt_ps(a, above), _mm_cmpgt_ps(b, above)),
                                       _mm_and_ps(_mm_cmplt_ps(a, below), _mm_cmplt_ps(b, below)));
      const auto open = lanes & ~static_cast<std::uint32_t>(_mm_movemask_ps(settled));
#else
      std::uint32_t open = 0;
      for (int lane = 0; lane < 4; ++lane) {
        d0[lane] = ((group.planes[0][lane] * light.x + group.planes[1][lane] * light.y) +
                    group.planes[2][lane] * light.z) + group.planes[3][lane] * light.w;
        d1[lane] = ((group.planes[4][lane] * light.x + group.planes[5][lane] * light.y) +
                    group.planes[6][lane] * light.z) + group.planes[7][lane] * light.w;
        const bool settled =
            (d0[lane] > margin && d1[lane] > margin) || (d0[lane] < -margin && d1[lane] < -margin);
        if (!settled) open |= 1u << lane;
      }
      open &= lanes;
#endif
      for (std::uint32_t bits = open; bits != 0; bits &= bits - 1) {
        const auto lane = static_cast<std::uint32_t>(std::countr_zero(bits));
        decide(leafEdges_[4 * g + lane], d0[lane], d1[lane]);
      }
    }
  }
  sortEdges(found_, sortSpare_);
  for (std::uint32_t f : found_) {
    const SilhouetteEdge& ends = caster_.edgeEnds[f >> 1];
    out.push_back((f & 1u) != 0 ? ends : SilhouetteEdge{ends.v1, ends.v0});
  }
  last_.keep(light, out);
}

}  // namespace stencil
