#include "geometry/adjacency.h"

#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace stencil {

namespace {

struct PairHash {
  std::size_t operator()(std::uint64_t key) const {
    // splitmix64 finaliser; raw (min << 32 | max) keys bucket badly with power-of-two tables.
    key ^= key >> 30;
    key *= 0xbf58476d1ce4e5b9ULL;
    key ^= key >> 27;
    key *= 0x94d049bb133111ebULL;
    key ^= key >> 31;
    return static_cast<std::size_t>(key);
  }
};

// Per-edge face counts, only needed while building.
struct Tally {
  std::uint32_t along = 0;    // faces walking v0 -> v1 (including face0)
  std::uint32_t against = 0;  // faces walking v1 -> v0
};

}  // namespace

bool AdjacencyReport::closedManifold() const {
  return borderEdges == 0 && nonManifoldEdges == 0 && inconsistentEdges == 0;
}

EdgeAdjacency buildEdgeAdjacency(const std::vector<std::uint32_t>& indices, std::size_t vertexCount) {
  if (indices.size() % 3 != 0) {
    throw std::invalid_argument("buildEdgeAdjacency: index count " + std::to_string(indices.size()) +
                                " is not a multiple of 3");
  }
  const std::size_t triangleCount = indices.size() / 3;
  if (triangleCount > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
    throw std::invalid_argument("buildEdgeAdjacency: too many triangles for int32 face numbers");
  }
  for (std::size_t i = 0; i < indices.size(); ++i) {
    if (indices[i] >= vertexCount) {
      throw std::invalid_argument("buildEdgeAdjacency: index " + std::to_string(indices[i]) +
                                  " at position " + std::to_string(i) + " is out of range (" +
                                  std::to_string(vertexCount) + " vertices)");
    }
  }

  EdgeAdjacency result;
  // A closed mesh has 1.5 edges per triangle.
  result.edges.reserve(triangleCount * 3 / 2 + 3);
  std::vector<Tally> tallies;
  tallies.reserve(result.edges.capacity());
  std::unordered_map<std::uint64_t, std::uint32_t, PairHash> lookup;
  lookup.reserve(result.edges.capacity());

  for (std::size_t t = 0; t < triangleCount; ++t) {
    const std::uint32_t* tri = &indices[3 * t];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) {
      result.degenerateTriangleIndices.push_back(static_cast<std::uint32_t>(t));
      continue;
    }
    const auto face = static_cast<std::int32_t>(t);
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = tri[k];
      const std::uint32_t b = tri[(k + 1) % 3];
      const std::uint64_t key = a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a);
      const auto [it, inserted] = lookup.try_emplace(key, static_cast<std::uint32_t>(result.edges.size()));
      if (inserted) {
        // The first face to touch an edge fixes its direction.
        result.edges.push_back(Edge{a, b, face, -1});
        tallies.push_back(Tally{1, 0});
        continue;
      }
      Edge& edge = result.edges[it->second];
      Tally& tally = tallies[it->second];
      const bool against = edge.v0 == b;
      if (against) {
        // Prefer a properly opposed face for face1, even if a same-way face got there first.
        if (tally.against == 0) edge.face1 = face;
        ++tally.against;
      } else {
        if (edge.face1 == -1) edge.face1 = face;
        ++tally.along;
      }
    }
  }

  for (std::size_t e = 0; e < result.edges.size(); ++e) {
    const Tally& tally = tallies[e];
    const std::uint32_t faces = tally.along + tally.against;
    const auto index = static_cast<std::uint32_t>(e);
    if (faces == 1) {
      result.borderEdgeIndices.push_back(index);
    } else if (faces >= 3) {
      result.nonManifoldEdgeIndices.push_back(index);
    } else if (tally.against == 0) {
      result.inconsistentEdgeIndices.push_back(index);
    }
  }
  result.report.borderEdges = result.borderEdgeIndices.size();
  result.report.nonManifoldEdges = result.nonManifoldEdgeIndices.size();
  result.report.inconsistentEdges = result.inconsistentEdgeIndices.size();
  result.report.degenerateTriangles = result.degenerateTriangleIndices.size();
  return result;
}

}  // namespace stencil
