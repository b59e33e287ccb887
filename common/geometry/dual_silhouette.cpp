#include "geometry/dual_silhouette.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>

namespace stencil {

namespace {

glm::vec4 minOf(const glm::vec4& a, const glm::vec4& b) {
  return glm::min(a, b);
}
glm::vec4 maxOf(const glm::vec4& a, const glm::vec4& b) {
  return glm::max(a, b);
}

}  // namespace

DualSilhouettes::DualSilhouettes(const SilhouetteCaster& caster, std::size_t maxLeaf, int maxDepth)
    : caster_(caster), maxLeaf_(std::max<std::size_t>(1, maxLeaf)), maxDepth_(maxDepth) {
  const std::size_t faceCount = caster.faceCount();
  planes_.resize(faceCount);
  for (std::size_t f = 0; f < faceCount; ++f) {
    const glm::dvec3 n(caster.nx[f], caster.ny[f], caster.nz[f]), a(caster.ax[f], caster.ay[f], caster.az[f]);
    const glm::dvec4 p(n, -glm::dot(n, a));
    const double length = glm::length(p);
    planes_[f] = length > 0.0 && std::isfinite(length) && glm::length(n) > 0.0 ? glm::vec4(p / length)
                                                                               : glm::vec4(0.0f);
    cornerScale_ = std::max(cornerScale_, static_cast<float>(glm::length(a)));
  }
  std::vector<std::uint32_t> inTree;
  const auto border = static_cast<std::int32_t>(faceCount);
  glm::vec4 lo(1.0f), hi(-1.0f);
  for (std::uint32_t e = 0; e < caster.edgeFaces.size(); ++e) {
    const SilhouetteCaster::EdgeFaces& ef = caster.edgeFaces[e];
    if (ef.face1 == border || planes_[ef.face0] == glm::vec4(0.0f) || planes_[ef.face1] == glm::vec4(0.0f)) {
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

bool DualSilhouettes::faces(std::int32_t f, const glm::vec4& light) const {
  // The brute force's own test and arithmetic (shadow_volume.cpp's facing pass).
  const auto t = static_cast<std::size_t>(f);
  const float x = caster_.nx[t] * (light.x - light.w * caster_.ax[t]);
  const float y = caster_.ny[t] * (light.y - light.w * caster_.ay[t]);
  const float z = caster_.nz[t] * (light.z - light.w * caster_.az[t]);
  return (x + y) + z > 0.0f;
}

namespace {

// The same four floats, bit for bit (so -0 differs from 0 and a NaN from itself: never reused).
bool sameBits(const glm::vec4& a, const glm::vec4& b) {
  return std::memcmp(&a, &b, sizeof a) == 0 && a == b;
}

}  // namespace

void DualSilhouettes::query(const glm::vec4& light, std::vector<SilhouetteEdge>& out) const {
  if (cached_ && sameBits(light, cachedLight_)) {
    stats_ = {0, 0, true};
    ++queriesReused_;
    out = cachedEdges_;
    return;
  }
  descend(light, out);
}

void DualSilhouettes::descend(const glm::vec4& light, std::vector<SilhouetteEdge>& out) const {
  stats_ = {};
  ++queriesRun_;
  out.clear();
  found_.clear();
  // The hyperplane P.L = 0 misses a box when P.L keeps one sign over it, by more than the rounding
  // of the unit planes and of the brute force's test (relative 1e-4, far above float's 6e-8 per
  // operation): only then is a cell left out.
  const float margin = 1e-4f * (std::abs(light.x) + std::abs(light.y) + std::abs(light.z) +
                                std::abs(light.w) * (1.0f + cornerScale_));
  const auto test = [&](std::uint32_t e) {
    ++stats_.edgesTested;
    const SilhouetteCaster::EdgeFaces& ef = caster_.edgeFaces[e];
    const bool lit0 = faces(ef.face0, light);
    const bool border = static_cast<std::size_t>(ef.face1) == caster_.faceCount();
    if (border || lit0 != faces(ef.face1, light)) found_.push_back(e);
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
    out.push_back(faces(ef.face0, light) ? ends : SilhouetteEdge{ends.v1, ends.v0});
  }
  cached_ = true;
  cachedLight_ = light;
  cachedEdges_ = out;
}

}  // namespace stencil
