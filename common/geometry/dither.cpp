#include "geometry/dither.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>

namespace stencil {

const char* patternName(PatternKind k) {
  switch (k) {
    case PatternKind::WhiteNoise: return "white noise";
    case PatternKind::Bayer: return "Bayer";
    case PatternKind::BlueNoise: return "blue noise";
    case PatternKind::LinearWipe: return "linear wipe";
    case PatternKind::RadialWipe: return "radial wipe";
    case PatternKind::ClockWipe: return "clock wipe";
  }
  return "?";
}

std::vector<std::uint32_t> bayerMatrix(int log2Side) {
  if (log2Side < 0 || log2Side > 8)
    throw std::invalid_argument("bayerMatrix: log2Side must be 0..8, got " + std::to_string(log2Side));
  std::vector<std::uint32_t> m{0};
  for (int side = 1; side < (1 << log2Side); side *= 2) {
    const int next = 2 * side;
    std::vector<std::uint32_t> grown(static_cast<std::size_t>(next * next));
    // Quadrant offsets in the order the recursion visits them: (0,0) +0, (1,0) +2, (0,1) +3, (1,1) +1.
    const std::uint32_t offset[2][2] = {{0, 2}, {3, 1}};  // [qy][qx]
    for (int y = 0; y < next; ++y)
      for (int x = 0; x < next; ++x)
        grown[static_cast<std::size_t>(y * next + x)] =
            4 * m[static_cast<std::size_t>((y % side) * side + x % side)] + offset[y / side][x / side];
    m = std::move(grown);
  }
  return m;
}

std::uint64_t pixelHash(std::uint32_t x, std::uint32_t y, std::uint32_t seed) {
  std::uint64_t z = (static_cast<std::uint64_t>(x) << 32 | y) ^ (0x9e3779b97f4a7c15ull * (seed + 1ull));
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

std::vector<std::uint32_t> voidAndCluster(int side, std::uint32_t seed, double sigma) {
  if (side < 2 || side > 256)
    throw std::invalid_argument("voidAndCluster: side must be 2..256, got " + std::to_string(side));
  if (!(sigma > 0.0)) throw std::invalid_argument("voidAndCluster: sigma must be positive");
  const std::size_t n = static_cast<std::size_t>(side) * static_cast<std::size_t>(side);
  // The Gaussian on the torus, by offset: kernel[dy * side + dx].
  std::vector<double> kernel(n);
  for (int dy = 0; dy < side; ++dy)
    for (int dx = 0; dx < side; ++dx) {
      const double wx = std::min(dx, side - dx), wy = std::min(dy, side - dy);
      kernel[static_cast<std::size_t>(dy * side + dx)] =
          std::exp(-(wx * wx + wy * wy) / (2.0 * sigma * sigma));
    }
  // Adds sign * the kernel centred on pixel j to every pixel's energy.
  auto splat = [&](std::vector<double>& energy, std::size_t j, double sign) {
    const int jx = static_cast<int>(j % static_cast<std::size_t>(side)),
              jy = static_cast<int>(j / static_cast<std::size_t>(side));
    for (int y = 0; y < side; ++y) {
      const int dy = (y - jy + side) % side;
      for (int x = 0; x < side; ++x) {
        const int dx = (x - jx + side) % side;
        energy[static_cast<std::size_t>(y * side + x)] +=
            sign * kernel[static_cast<std::size_t>(dy * side + dx)];
      }
    }
  };
  // The pixel with the highest (tightest cluster) or lowest (largest void) energy among those
  // whose bit is `bit`; the lowest index wins a tie.
  auto extreme = [&](const std::vector<double>& energy, const std::vector<bool>& bits, bool bit,
                     bool highest) {
    std::size_t best = n;
    for (std::size_t i = 0; i < n; ++i) {
      if (bits[i] != bit) continue;
      if (best == n || (highest ? energy[i] > energy[best] : energy[i] < energy[best])) best = i;
    }
    return best;
  };

  // The initial binary pattern: a tenth of the pixels, those with the smallest hashes.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const auto ha =
        pixelHash(static_cast<std::uint32_t>(a % side), static_cast<std::uint32_t>(a / side), seed);
    const auto hb =
        pixelHash(static_cast<std::uint32_t>(b % side), static_cast<std::uint32_t>(b / side), seed);
    return ha != hb ? ha < hb : a < b;
  });
  const std::size_t ones = std::max<std::size_t>(1, n / 10);
  std::vector<bool> prototype(n, false);
  std::vector<double> energy(n, 0.0);
  for (std::size_t i = 0; i < ones; ++i) {
    prototype[order[i]] = true;
    splat(energy, order[i], 1.0);
  }
  // Relax it: move the tightest cluster's pixel into the largest void until that is where it was.
  for (std::size_t step = 0; step < 10 * n; ++step) {
    const std::size_t cluster = extreme(energy, prototype, true, true);
    prototype[cluster] = false;
    splat(energy, cluster, -1.0);
    const std::size_t voidAt = extreme(energy, prototype, false, false);
    prototype[voidAt] = true;
    splat(energy, voidAt, 1.0);
    if (voidAt == cluster) break;
  }

  std::vector<std::uint32_t> rank(n, 0);
  // Phase 1: take the prototype's pixels away, tightest cluster first; each gets the rank of the
  // count left.
  {
    std::vector<bool> bits = prototype;
    std::vector<double> e = energy;
    for (std::size_t r = ones; r-- > 0;) {
      const std::size_t cluster = extreme(e, bits, true, true);
      bits[cluster] = false;
      splat(e, cluster, -1.0);
      rank[cluster] = static_cast<std::uint32_t>(r);
    }
  }
  // Phases 2 and 3: fill the largest void, one pixel at a time, up to every pixel. (Ulichney's
  // phase 3 takes the tightest cluster of the zeros; with a linear filter their energy is a
  // constant minus the ones', so that is the same pixel.)
  {
    std::vector<bool> bits = prototype;
    std::vector<double> e = energy;
    for (std::size_t r = ones; r < n; ++r) {
      const std::size_t voidAt = extreme(e, bits, false, false);
      bits[voidAt] = true;
      splat(e, voidAt, 1.0);
      rank[voidAt] = static_cast<std::uint32_t>(r);
    }
  }
  return rank;
}

std::vector<std::uint8_t> equalize(const std::vector<double>& keys, const std::vector<std::uint64_t>& ties) {
  if (keys.size() != ties.size()) throw std::invalid_argument("equalize: keys and ties differ in size");
  const std::size_t n = keys.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (keys[a] != keys[b]) return keys[a] < keys[b];
    if (ties[a] != ties[b]) return ties[a] < ties[b];
    return a < b;
  });
  std::vector<std::uint8_t> level(n);
  for (std::size_t r = 0; r < n; ++r) level[order[r]] = static_cast<std::uint8_t>(256 * r / n);
  return level;
}

std::vector<std::uint8_t> makePattern(PatternKind kind, int width, int height, std::uint32_t seed,
                                      int blueNoiseTileSide) {
  if (width < 1 || height < 1) throw std::invalid_argument("makePattern: the size must be at least 1x1");
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::vector<double> keys(n, 0.0);
  std::vector<std::uint64_t> ties(n, 0);
  std::vector<std::uint32_t> tile;
  int tileSide = 1;
  if (kind == PatternKind::Bayer) tile = bayerMatrix(4), tileSide = 16;
  if (kind == PatternKind::BlueNoise)
    tile = voidAndCluster(blueNoiseTileSide, seed), tileSide = blueNoiseTileSide;
  const double cx = 0.5 * width, cy = 0.5 * height;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i =
          static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
      const std::uint64_t hash =
          pixelHash(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), seed);
      const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
      ties[i] = hash;
      switch (kind) {
        case PatternKind::WhiteNoise: break;  // the hash alone orders the pixels
        case PatternKind::Bayer:
        case PatternKind::BlueNoise:
          keys[i] = tile[static_cast<std::size_t>((y % tileSide) * tileSide + x % tileSide)];
          break;
        case PatternKind::LinearWipe:
          keys[i] = x;
          ties[i] = static_cast<std::uint64_t>(y);  // a column fills bottom to top
          break;
        case PatternKind::RadialWipe: keys[i] = dx * dx + dy * dy; break;
        case PatternKind::ClockWipe: {
          double a = std::atan2(dx, dy);  // 0 at twelve o'clock, growing clockwise
          if (a < 0) a += 2.0 * std::numbers::pi;
          keys[i] = a;
          break;
        }
      }
    }
  return equalize(keys, ties);
}

std::uint64_t countBelow(const std::vector<std::uint8_t>& pattern, int k) {
  std::uint64_t count = 0;
  for (std::uint8_t v : pattern) count += v < k;
  return count;
}

double coverageVariance(const std::vector<std::uint8_t>& pattern, int width, int height, int k, int window) {
  if (width < 1 || height < 1 ||
      pattern.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    throw std::invalid_argument("coverageVariance: the pattern is not width * height values");
  if (window < 1 || window > width || window > height)
    throw std::invalid_argument("coverageVariance: the " + std::to_string(window) +
                                "-pixel window does not fit");
  // A summed-area table of "below k", one row and column of zeros in front.
  const std::size_t w1 = static_cast<std::size_t>(width) + 1;
  std::vector<std::uint32_t> sat(w1 * (static_cast<std::size_t>(height) + 1), 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t at = static_cast<std::size_t>(y + 1) * w1 + static_cast<std::size_t>(x + 1);
      sat[at] = (pattern[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                         static_cast<std::size_t>(x)] < k) +
                sat[at - 1] + sat[at - w1] - sat[at - w1 - 1];
    }
  double sum = 0, sumSquares = 0;
  std::size_t windows = 0;
  const double area = static_cast<double>(window) * window;
  for (int y = 0; y + window <= height; ++y)
    for (int x = 0; x + window <= width; ++x) {
      const auto at = [&](int xx, int yy) {
        return sat[static_cast<std::size_t>(yy) * w1 + static_cast<std::size_t>(xx)];
      };
      const double c =
          static_cast<double>(at(x + window, y + window) + at(x, y) - at(x, y + window) - at(x + window, y)) /
          area;
      sum += c, sumSquares += c * c, ++windows;
    }
  const double mean = sum / static_cast<double>(windows);
  return std::max(0.0, sumSquares / static_cast<double>(windows) - mean * mean);
}

}  // namespace stencil
