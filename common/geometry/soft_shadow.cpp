#include "geometry/soft_shadow.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace stencil {

double radicalInverse(int base, std::uint64_t index) {
  if (base < 2) throw std::invalid_argument("radicalInverse: base must be at least 2");
  const double inverse = 1.0 / base;
  double result = 0.0, digitWeight = inverse;
  for (; index > 0; index /= static_cast<std::uint64_t>(base), digitWeight *= inverse)
    result += static_cast<double>(index % static_cast<std::uint64_t>(base)) * digitWeight;
  return result;
}

glm::ivec2 sampleGrid(int n) {
  if (n < 1) throw std::invalid_argument("sampleGrid: n must be at least 1");
  int rows = 1;
  for (int r = 1; r * r <= n; ++r)
    if (n % r == 0) rows = r;
  return {rows, n / rows};
}

namespace {

// A small, fixed pseudo-random stream (SplitMix64): the same jitter on every machine.
struct SplitMix {
  std::uint64_t state;
  double next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
  }
};

}  // namespace

std::vector<glm::vec2> unitSquareSamples(SamplePattern pattern, int n, int round) {
  if (n < 1) throw std::invalid_argument("unitSquareSamples: n must be at least 1");
  if (round < 0) throw std::invalid_argument("unitSquareSamples: round must not be negative");
  std::vector<glm::vec2> samples;
  samples.reserve(static_cast<std::size_t>(n));
  if (pattern == SamplePattern::Halton) {
    const std::uint64_t first = static_cast<std::uint64_t>(round) * static_cast<std::uint64_t>(n) + 1;
    for (std::uint64_t i = first; i < first + static_cast<std::uint64_t>(n); ++i)
      samples.push_back({static_cast<float>(radicalInverse(2, i)), static_cast<float>(radicalInverse(3, i))});
    return samples;
  }
  const glm::ivec2 grid = sampleGrid(n);  // rows along the square's y, columns along x
  SplitMix random{0x5EEDull + static_cast<std::uint64_t>(round) * 0x100000001B3ull +
                  static_cast<std::uint64_t>(n)};
  for (int row = 0; row < grid.x; ++row)
    for (int column = 0; column < grid.y; ++column) {
      double u = 0.5, v = 0.5;
      if (pattern == SamplePattern::Jittered) {
        u = random.next();
        v = random.next();
      }
      samples.push_back({static_cast<float>((column + u) / grid.y), static_cast<float>((row + v) / grid.x)});
    }
  return samples;
}

glm::vec2 concentricDisk(glm::vec2 unit) {
  const double a = 2.0 * unit.x - 1.0, b = 2.0 * unit.y - 1.0;
  if (a == 0.0 && b == 0.0) return {0.0f, 0.0f};
  const double quarter = std::numbers::pi / 4.0;
  double r, phi;
  if (std::abs(a) > std::abs(b)) {
    r = a;
    phi = quarter * (b / a);
  } else {
    r = b;
    phi = 2.0 * quarter - quarter * (a / b);
  }
  return {static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi))};
}

glm::vec3 lightPoint(const AreaLight& light, glm::vec2 unit) {
  if (light.shape == LightShape::Disk) {
    const glm::vec2 d = concentricDisk(unit) * (0.5f * light.size.x);
    return light.centre + glm::vec3(d.x, 0.0f, d.y);
  }
  return light.centre + glm::vec3((unit.x - 0.5f) * light.size.x, 0.0f, (unit.y - 0.5f) * light.size.y);
}

std::vector<glm::dvec2> lightOutline(const AreaLight& light, int diskSides) {
  const glm::dvec2 c(light.centre.x, light.centre.z);
  if (light.shape == LightShape::Disk) {
    std::vector<glm::dvec2> outline;
    const double r = 0.5 * light.size.x;
    for (int i = 0; i < diskSides; ++i) {
      const double a = 2.0 * std::numbers::pi * i / diskSides;
      outline.push_back(c + r * glm::dvec2(std::cos(a), std::sin(a)));
    }
    return outline;
  }
  const glm::dvec2 h(0.5 * light.size.x, 0.5 * light.size.y);
  // Counter-clockwise in the (x, z) plane.
  return {c + glm::dvec2(-h.x, -h.y), c + glm::dvec2(h.x, -h.y), c + glm::dvec2(h.x, h.y),
          c + glm::dvec2(-h.x, h.y)};
}

double straightEdgePenumbraWidth(double W, double H, double h) {
  if (!(h > 0.0 && h < H) || !(W >= 0.0))
    throw std::invalid_argument("straightEdgePenumbraWidth: needs 0 < h < H and W >= 0");
  return W * h / (H - h);
}

double straightEdgeVisibleFraction(double s, double W, double H, double h) {
  const double width = straightEdgePenumbraWidth(W, H, h);
  if (width == 0.0) return s < 0.0 ? 0.0 : 1.0;
  return std::clamp(s / width, 0.0, 1.0);
}

double polygonArea(const std::vector<glm::dvec2>& p) {
  double twice = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const glm::dvec2& a = p[i];
    const glm::dvec2& b = p[(i + 1) % p.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;
}

std::vector<glm::dvec2> clipConvex(const std::vector<glm::dvec2>& subject,
                                   const std::vector<glm::dvec2>& clip) {
  std::vector<glm::dvec2> out = subject;
  for (std::size_t e = 0; e < clip.size() && !out.empty(); ++e) {
    const glm::dvec2 a = clip[e], b = clip[(e + 1) % clip.size()];
    // Inside: to the left of a -> b (the clip polygon is counter-clockwise).
    auto side = [&](const glm::dvec2& p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); };
    std::vector<glm::dvec2> in = std::move(out);
    out.clear();
    for (std::size_t i = 0; i < in.size(); ++i) {
      const glm::dvec2 p = in[i], q = in[(i + 1) % in.size()];
      const double sp = side(p), sq = side(q);
      if (sp >= 0.0) out.push_back(p);
      if ((sp >= 0.0) != (sq >= 0.0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
    }
  }
  return out;
}

std::vector<glm::dvec2> convexHull(std::vector<glm::dvec2> points) {
  std::sort(points.begin(), points.end(),
            [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (points.size() < 3) return points;
  std::vector<glm::dvec2> hull(2 * points.size());
  auto cross = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::size_t k = 0;
  for (const glm::dvec2& p : points) {  // lower hull
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0.0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {  // upper hull
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

double visibleFraction(const AreaLight& light, const std::vector<glm::vec3>& occluderCorners,
                       const glm::vec3& receiver) {
  const double H = light.centre.y, y0 = receiver.y;
  std::vector<glm::dvec2> projected;
  for (const glm::vec3& c : occluderCorners) {
    if (!(c.y > y0 && c.y < H))
      throw std::invalid_argument(
          "visibleFraction: an occluder corner is not between the receiver and the light");
    // The ray from the receiver through the corner, continued to the light's plane.
    const double t = (H - y0) / (c.y - y0);
    projected.push_back({receiver.x + t * (c.x - receiver.x), receiver.z + t * (c.z - receiver.z)});
  }
  const std::vector<glm::dvec2> outline = lightOutline(light);
  const double area = polygonArea(outline);
  const std::vector<glm::dvec2> covered = clipConvex(convexHull(projected), outline);
  const double coveredArea = covered.size() < 3 ? 0.0 : polygonArea(covered);
  return std::clamp(1.0 - coveredArea / area, 0.0, 1.0);
}

}  // namespace stencil
