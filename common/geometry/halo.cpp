#include "geometry/halo.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace stencil {

namespace {

std::size_t pixelCount(glm::ivec2 size) {
  if (size.x < 0 || size.y < 0) throw std::invalid_argument("negative picture size");
  return static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y);
}

void checkSize(const std::vector<std::uint8_t>& mask, glm::ivec2 size, const char* what) {
  if (mask.size() != pixelCount(size))
    throw std::invalid_argument(std::string(what) + " has " + std::to_string(mask.size()) + " pixels, not " +
                                std::to_string(pixelCount(size)));
}

// One line of the squared distance transform: d[q] = min over p of (q - p)^2 + f[p], the lower
// envelope of the parabolas rooted at each p (v: their roots in order, z: where each takes over).
void squaredLine(const std::vector<double>& f, std::vector<double>& d, std::vector<std::size_t>& v,
                 std::vector<double>& z, std::size_t n) {
  const auto meet = [&](std::size_t q, std::size_t p) {  // where the parabolas of q and p cross
    const double dq = static_cast<double>(q), dp = static_cast<double>(p);
    return ((f[q] + dq * dq) - (f[p] + dp * dp)) / (2.0 * (dq - dp));
  };
  std::size_t k = 0;
  v[0] = 0;
  z[0] = -std::numeric_limits<double>::infinity();
  z[1] = std::numeric_limits<double>::infinity();
  for (std::size_t q = 1; q < n; ++q) {
    double s = meet(q, v[k]);
    while (s <= z[k]) {  // z[0] is -infinity: the loop stops at the first parabola
      --k;
      s = meet(q, v[k]);
    }
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = std::numeric_limits<double>::infinity();
  }
  k = 0;
  for (std::size_t q = 0; q < n; ++q) {
    while (z[k + 1] < static_cast<double>(q)) ++k;
    const double dq = static_cast<double>(q) - static_cast<double>(v[k]);
    d[q] = dq * dq + f[v[k]];
  }
}

}  // namespace

std::vector<float> distanceTransform(const std::vector<std::uint8_t>& seeds, glm::ivec2 size) {
  checkSize(seeds, size, "seed mask");
  const std::size_t w = static_cast<std::size_t>(size.x), h = static_cast<std::size_t>(size.y);
  constexpr double kFar = 1e20;  // no seed in this column yet: far beyond any picture
  std::vector<double> grid(seeds.size());
  bool any = false;
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    grid[i] = seeds[i] ? 0.0 : kFar;
    any = any || seeds[i];
  }
  if (!any) return std::vector<float>(seeds.size(), std::numeric_limits<float>::infinity());
  const std::size_t n = std::max(w, h);
  std::vector<double> f(n), d(n), z(n + 1);
  std::vector<std::size_t> v(n);
  for (std::size_t x = 0; x < w; ++x) {  // columns
    for (std::size_t y = 0; y < h; ++y) f[y] = grid[y * w + x];
    squaredLine(f, d, v, z, h);
    for (std::size_t y = 0; y < h; ++y) grid[y * w + x] = d[y];
  }
  for (std::size_t y = 0; y < h; ++y) {  // rows
    for (std::size_t x = 0; x < w; ++x) f[x] = grid[y * w + x];
    squaredLine(f, d, v, z, w);
    for (std::size_t x = 0; x < w; ++x) grid[y * w + x] = d[x];
  }
  std::vector<float> distance(seeds.size());
  for (std::size_t i = 0; i < grid.size(); ++i) distance[i] = static_cast<float>(std::sqrt(grid[i]));
  return distance;
}

HaloMeasure measureHalo(const std::vector<std::uint8_t>& object, const std::vector<std::uint8_t>& blends,
                        const std::vector<std::uint8_t>& blocked, glm::ivec2 size) {
  checkSize(object, size, "object mask");
  checkSize(blends, size, "blend counts");
  if (!blocked.empty()) checkSize(blocked, size, "blocked mask");
  const auto isBlocked = [&](std::size_t i) { return !blocked.empty() && blocked[i] && !object[i]; };
  HaloMeasure m;
  std::vector<std::uint8_t> outside(object.size());
  for (std::size_t i = 0; i < object.size(); ++i) {
    const bool obj = object[i] != 0, blended = blends[i] > 0;
    m.objectPixels += obj;
    m.haloPixels += blended && !obj;
    m.coveredPixels += blended && obj;
    m.multiPixels += blends[i] > 1;
    m.blends += blends[i];
    outside[i] = !obj && !blended && !isBlocked(i);
  }
  const auto at = [&](int x, int y) {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(size.x) + static_cast<std::size_t>(x);
  };
  const auto inside = [&](int x, int y) { return x >= 0 && y >= 0 && x < size.x && y < size.y; };
  const std::vector<float> toObject = distanceTransform(object, size);
  double sum = 0.0;
  m.widthMin = std::numeric_limits<double>::infinity();
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      if (!object[at(x, y)]) continue;
      bool outline = false;
      for (const auto& [dx, dy] : {std::pair{-1, 0}, std::pair{1, 0}, std::pair{0, -1}, std::pair{0, 1}})
        outline = outline || (inside(x + dx, y + dy) && !object[at(x + dx, y + dy)]);
      if (!outline) continue;
      double nx = 0.0, ny = 0.0;  // towards the non-object pixels nearby
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx)
          if (inside(x + dx, y + dy) && !object[at(x + dx, y + dy)]) {
            nx += dx;
            ny += dy;
          }
      const double length = std::sqrt(nx * nx + ny * ny);
      if (length == 0.0) continue;  // a one-pixel hole: no direction
      nx /= length;
      ny /= length;
      // March in half-pixel steps: out of the object, through the halo, to what lies beyond.
      double leftObject = -1.0, width = -1.0;
      bool sampled = false;
      for (double t = 0.5; t < 4.0 * static_cast<double>(std::max(size.x, size.y)); t += 0.5) {
        const int qx = static_cast<int>(std::lround(x + t * nx)),
                  qy = static_cast<int>(std::lround(y + t * ny));
        if (!inside(qx, qy)) break;
        const std::size_t q = at(qx, qy);
        if (leftObject < 0.0) {
          if (object[q]) continue;
          leftObject = t - 0.5;
        }
        // Across a filled gap into the object again, or into halo that is another part's: filled.
        if (object[q] || static_cast<double>(toObject[q]) < t - leftObject - 1.5) {
          ++m.filledPixels;
          break;
        }
        if (isBlocked(q)) break;
        if (outside[q]) {
          width = t - 0.5 - leftObject;
          sampled = true;
          break;
        }
      }
      if (!sampled) continue;
      ++m.outlinePixels;
      sum += width;
      m.widthMin = std::min(m.widthMin, width);
      m.widthMax = std::max(m.widthMax, width);
    }
  if (m.outlinePixels == 0) {
    m.widthMin = 0.0;
    return m;
  }
  m.widthMean = sum / static_cast<double>(m.outlinePixels);
  return m;
}

Mesh smoothNormals(const Mesh& mesh) {
  validateMesh(mesh);
  if (mesh.normals.empty()) throw std::invalid_argument("smoothNormals: the mesh has no normals");
  std::map<std::tuple<float, float, float>, glm::vec3> sums;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 p = mesh.positions[i];
    sums[{p.x, p.y, p.z}] += mesh.normals[i];
  }
  Mesh out = mesh;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 p = mesh.positions[i];
    const glm::vec3 s = sums[{p.x, p.y, p.z}];
    const float length = std::sqrt(s.x * s.x + s.y * s.y + s.z * s.z);
    out.normals[i] = length > 0.0f ? s / length : mesh.normals[i];
  }
  return out;
}

}  // namespace stencil
