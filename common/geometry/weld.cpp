#include "geometry/weld.h"

#include <cmath>
#include <cstddef>
#include <cstring>
#include <glm/geometric.hpp>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace stencil {

namespace {

std::uint64_t mix(std::uint64_t h) {
  // splitmix64 finaliser: float bit patterns cluster, so spread them before bucketing.
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ULL;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebULL;
  h ^= h >> 31;
  return h;
}

struct ExactKey {
  std::uint32_t x, y, z;
  bool operator==(const ExactKey& o) const { return x == o.x && y == o.y && z == o.z; }
};

std::uint32_t canonicalBits(float value) {
  // -0.0 == +0.0 but their bits differ; hash them alike.
  const float canonical = value == 0.0f ? 0.0f : value;
  std::uint32_t bits;
  std::memcpy(&bits, &canonical, sizeof bits);
  return bits;
}

struct ExactKeyHash {
  std::size_t operator()(const ExactKey& k) const {
    const std::uint64_t h = (static_cast<std::uint64_t>(k.x) << 32 | k.y) ^ mix(k.z);
    return static_cast<std::size_t>(mix(h));
  }
};

struct CellKey {
  std::int64_t x, y, z;
  bool operator==(const CellKey& o) const { return x == o.x && y == o.y && z == o.z; }
};

struct CellKeyHash {
  std::size_t operator()(const CellKey& k) const {
    std::uint64_t h = mix(static_cast<std::uint64_t>(k.x));
    h = mix(h ^ static_cast<std::uint64_t>(k.y));
    h = mix(h ^ static_cast<std::uint64_t>(k.z));
    return static_cast<std::size_t>(h);
  }
};

void validateForWeld(const Mesh& mesh) {
  validateMesh(mesh);
  if (mesh.positions.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw std::invalid_argument("weldByPosition: too many vertices for 32-bit indices");
  }
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3& p = mesh.positions[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      throw std::invalid_argument("weldByPosition: vertex " + std::to_string(i) +
                                  " has a non-finite position");
    }
  }
}

// Builds the welded mesh once remap is known. `firstOld[n]` is the first input
// vertex that became welded vertex n.
WeldResult assemble(const Mesh& mesh, std::vector<std::uint32_t> remap,
                    const std::vector<std::uint32_t>& firstOld) {
  WeldResult result;
  Mesh& out = result.mesh;
  out.positions.reserve(firstOld.size());
  for (std::uint32_t old : firstOld) {
    out.positions.push_back(mesh.positions[old]);
  }
  if (!mesh.normals.empty()) {
    out.normals.assign(firstOld.size(), glm::vec3(0.0f));
    for (std::size_t i = 0; i < remap.size(); ++i) {
      out.normals[remap[i]] += mesh.normals[i];
    }
    for (std::size_t n = 0; n < out.normals.size(); ++n) {
      const float len = glm::length(out.normals[n]);
      out.normals[n] = len > 0.0f ? out.normals[n] / len : mesh.normals[firstOld[n]];
    }
  }
  out.indices.reserve(mesh.indices.size());
  for (std::uint32_t index : mesh.indices) {
    out.indices.push_back(remap[index]);
  }
  result.remap = std::move(remap);
  return result;
}

}  // namespace

WeldResult weldByPosition(const Mesh& mesh) {
  validateForWeld(mesh);
  std::unordered_map<ExactKey, std::uint32_t, ExactKeyHash> lookup;
  lookup.reserve(mesh.positions.size());
  std::vector<std::uint32_t> remap(mesh.positions.size());
  std::vector<std::uint32_t> firstOld;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3& p = mesh.positions[i];
    const ExactKey key{canonicalBits(p.x), canonicalBits(p.y), canonicalBits(p.z)};
    const auto [it, inserted] = lookup.try_emplace(key, static_cast<std::uint32_t>(firstOld.size()));
    if (inserted) {
      firstOld.push_back(static_cast<std::uint32_t>(i));
    }
    remap[i] = it->second;
  }
  return assemble(mesh, std::move(remap), firstOld);
}

WeldResult weldByPosition(const Mesh& mesh, float tolerance) {
  if (!(tolerance >= 0.0f) || !std::isfinite(tolerance)) {
    throw std::invalid_argument("weldByPosition: tolerance must be finite and >= 0, got " +
                                std::to_string(tolerance));
  }
  if (tolerance == 0.0f) {
    return weldByPosition(mesh);
  }
  validateForWeld(mesh);

  // Cell coordinates must fit an int64 with room for the +-1 neighbour offsets.
  constexpr double cellLimit = 4.0e18;
  auto cellOf = [&](const glm::vec3& p) {
    const glm::dvec3 scaled = glm::dvec3(p) / static_cast<double>(tolerance);
    for (int axis = 0; axis < 3; ++axis) {
      if (std::abs(scaled[axis]) > cellLimit) {
        throw std::invalid_argument("weldByPosition: tolerance " + std::to_string(tolerance) +
                                    " is too small for the coordinate range");
      }
    }
    return CellKey{static_cast<std::int64_t>(std::floor(scaled.x)),
                   static_cast<std::int64_t>(std::floor(scaled.y)),
                   static_cast<std::int64_t>(std::floor(scaled.z))};
  };

  // Points within `tolerance` of each other are at most one cell apart per axis.
  std::unordered_map<CellKey, std::vector<std::uint32_t>, CellKeyHash> grid;
  grid.reserve(mesh.positions.size());
  const double toleranceSquared = static_cast<double>(tolerance) * static_cast<double>(tolerance);
  std::vector<std::uint32_t> remap(mesh.positions.size());
  std::vector<std::uint32_t> firstOld;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3& p = mesh.positions[i];
    const CellKey cell = cellOf(p);
    std::uint32_t match = std::numeric_limits<std::uint32_t>::max();
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find(CellKey{cell.x + dx, cell.y + dy, cell.z + dz});
          if (it == grid.end()) continue;
          for (std::uint32_t candidate : it->second) {
            // Lowest index wins so the result does not depend on hash order.
            if (candidate >= match) continue;
            const glm::dvec3 d = glm::dvec3(mesh.positions[firstOld[candidate]]) - glm::dvec3(p);
            if (glm::dot(d, d) <= toleranceSquared) match = candidate;
          }
        }
      }
    }
    if (match == std::numeric_limits<std::uint32_t>::max()) {
      match = static_cast<std::uint32_t>(firstOld.size());
      firstOld.push_back(static_cast<std::uint32_t>(i));
      grid[cell].push_back(match);
    }
    remap[i] = match;
  }
  return assemble(mesh, std::move(remap), firstOld);
}

}  // namespace stencil
