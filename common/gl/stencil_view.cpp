#include "gl/stencil_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>

namespace stencil {
namespace {

using Rgb = std::array<std::uint8_t, 3>;

// 3x5 pixel digits, one bit per pixel, rows top to bottom, so the legend needs no font file.
constexpr std::array<std::uint16_t, 10> kDigits = {
    0b111'101'101'101'111, 0b010'110'010'010'111, 0b111'001'111'100'111, 0b111'001'111'001'111,
    0b101'101'111'001'001, 0b111'100'111'001'111, 0b111'100'111'101'111, 0b111'001'001'001'001,
    0b111'101'111'101'111, 0b111'101'111'001'111};

void fillRect(Image& img, int x0, int y0, int w, int h, Rgb c) {
  for (int y = std::max(0, y0); y < std::min(img.height, y0 + h); ++y)
    for (int x = std::max(0, x0); x < std::min(img.width, x0 + w); ++x) {
      std::uint8_t* p = img.at(x, y);
      p[0] = c[0], p[1] = c[1], p[2] = c[2], p[3] = 255;
    }
}

constexpr std::uint16_t kPlus = 0b000'010'111'010'000;
constexpr std::uint16_t kOpen = 0b001'010'010'010'001, kClose = 0b100'010'010'010'100;
constexpr std::uint16_t kPoint = 0b000'000'000'000'010;
constexpr std::uint16_t kHour = 0b100'100'111'101'101;  // 'h'
// The few letters the window's legends need: the grey view's rule ("v x 255/7"), the depth view's "far".
constexpr std::uint16_t kV = 0b000'101'101'101'010, kX = 0b000'101'010'101'000, kSlash = 0b001'001'010'100'100;
constexpr std::uint16_t kF = 0b011'100'110'100'100, kA = 0b000'011'101'101'011, kR = 0b000'101'110'100'100;

// Draws digits, '+', '.', '/', 'h', 'v', 'x', 'f', 'a', 'r' and parentheses with the font scaled by
// `scale`; returns the width drawn.
int drawText(Image& img, int x, int y, const std::string& text, int scale, Rgb c) {
  for (size_t i = 0; i < text.size(); ++i) {
    const std::uint16_t glyph = text[i] == '+'   ? kPlus
                                : text[i] == '/' ? kSlash
                                : text[i] == 'v' ? kV
                                : text[i] == 'x' ? kX
                                : text[i] == 'f' ? kF
                                : text[i] == 'a' ? kA
                                : text[i] == 'r' ? kR
                                : text[i] == '(' ? kOpen
                                : text[i] == ')' ? kClose
                                : text[i] == '.' ? kPoint
                                : text[i] == 'h' ? kHour
                                : text[i] >= '0' && text[i] <= '9'
                                    ? kDigits[static_cast<size_t>(text[i] - '0')]
                                    : std::uint16_t{0};  // a blank
    for (int row = 0; row < 5; ++row)
      for (int col = 0; col < 3; ++col)
        if (glyph & (1u << (14 - (row * 3 + col))))
          fillRect(img, x + (static_cast<int>(i) * 4 + col) * scale, y + row * scale, scale, scale, c);
  }
  return static_cast<int>(text.size()) * 4 * scale;
}

int drawNumber(Image& img, int x, int y, int number, int scale, Rgb c) {
  return drawText(img, x, y, std::to_string(number), scale, c);
}

int textWidth(const std::string& text, int scale) {
  return static_cast<int>(text.size()) * 4 * scale - scale;
}

}  // namespace

namespace {

using Lab = std::array<float, 3>;

// sRGB bytes to CIELAB (D65 white), and back (out-of-gamut channels clamped).
float linear(std::uint8_t c) {
  const float v = static_cast<float>(c) / 255.0f;
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}
std::uint8_t encoded(float v) {
  v = std::clamp(v, 0.0f, 1.0f);
  const float e = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
  return static_cast<std::uint8_t>(std::lround(255.0f * e));
}
constexpr float kWhite[3] = {0.95047f, 1.0f, 1.08883f};
constexpr float kDelta = 6.0f / 29.0f;

Lab toLab(const Rgb& c) {
  const float r = linear(c[0]), g = linear(c[1]), b = linear(c[2]);
  const float xyz[3] = {0.4124f * r + 0.3576f * g + 0.1805f * b, 0.2126f * r + 0.7152f * g + 0.0722f * b,
                        0.0193f * r + 0.1192f * g + 0.9505f * b};
  float f[3];
  for (int i = 0; i < 3; ++i) {
    const float t = xyz[i] / kWhite[i];
    f[i] = t > kDelta * kDelta * kDelta ? std::cbrt(t) : t / (3 * kDelta * kDelta) + 4.0f / 29.0f;
  }
  return {116.0f * f[1] - 16.0f, 500.0f * (f[0] - f[1]), 200.0f * (f[1] - f[2])};
}

Rgb fromLab(const Lab& lab) {
  const float fy = (lab[0] + 16.0f) / 116.0f, f[3] = {fy + lab[1] / 500.0f, fy, fy - lab[2] / 200.0f};
  float xyz[3];
  for (int i = 0; i < 3; ++i)
    xyz[i] = kWhite[i] * (f[i] > kDelta ? f[i] * f[i] * f[i] : 3 * kDelta * kDelta * (f[i] - 4.0f / 29.0f));
  const float x = xyz[0], y = xyz[1], z = xyz[2];
  return {encoded(3.2406f * x - 1.5372f * y - 0.4986f * z), encoded(-0.9689f * x + 1.8758f * y + 0.0415f * z),
          encoded(0.0557f * x - 0.2040f * y + 1.0570f * z)};
}

}  // namespace

Rgb stencilColour(std::uint8_t value) {
  static constexpr std::array<Rgb, 12> kPalette = {{{230, 25, 75},
                                                    {60, 180, 75},
                                                    {255, 225, 25},
                                                    {0, 130, 200},
                                                    {245, 130, 48},
                                                    {145, 30, 180},
                                                    {70, 240, 240},
                                                    {240, 50, 230},
                                                    {210, 245, 60},
                                                    {250, 190, 212},
                                                    {0, 128, 128},
                                                    {170, 110, 40}}};
  if (value == 0) return {0, 0, 0};
  if (value <= kPalette.size()) return kPalette[value - 1u];
  // 13..255: the hue turns by the golden angle from one value to the next and the lightness
  // cycles through three levels, so neighbours differ in both; the chroma fits most hues in sRGB.
  const int k = value - 13;
  const float hue =
      (std::numbers::pi_v<float> / 180.0f) * (std::fmod(static_cast<float>(k) * 137.508f + 20.0f, 360.0f));
  static constexpr float kLightness[3] = {62.0f, 78.0f, 48.0f};
  const float chroma = 36.0f;
  return fromLab({kLightness[k % 3], chroma * std::cos(hue), chroma * std::sin(hue)});
}

float colourDistance(const Rgb& a, const Rgb& b) {
  const Lab p = toLab(a), q = toLab(b);
  return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                   (p[2] - q[2]) * (p[2] - q[2]));
}

std::array<Rgb, 256> stencilPictureColours(const std::vector<std::uint64_t>& histogram) {
  // The colours a clashing value may take instead: every sRGB colour whose channels are multiples
  // of 255/11, 1728 colours spread over the whole gamut (fine enough that 24 values always find
  // colours kStencilDistinct apart; 255/7's 512 did not).
  struct Candidate {
    Rgb rgb;
    Lab lab;
  };
  static const std::vector<Candidate> kCandidates = [] {
    std::vector<Candidate> all;
    for (int r = 0; r < 12; ++r)
      for (int g = 0; g < 12; ++g)
        for (int b = 0; b < 12; ++b) {
          const Rgb c{static_cast<std::uint8_t>(r * 255 / 11), static_cast<std::uint8_t>(g * 255 / 11),
                      static_cast<std::uint8_t>(b * 255 / 11)};
          all.push_back({c, toLab(c)});
        }
    return all;
  }();
  const auto distance = [](const Lab& p, const Lab& q) {
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                     (p[2] - q[2]) * (p[2] - q[2]));
  };
  std::array<Rgb, 256> colours;
  for (int v = 0; v < 256; ++v)
    colours[static_cast<std::size_t>(v)] = stencilColour(static_cast<std::uint8_t>(v));
  const auto count = [&](int v) {
    return static_cast<std::size_t>(v) < histogram.size() ? histogram[static_cast<std::size_t>(v)] : 0;
  };
  std::vector<int> order;
  for (int v = 1; v < 256; ++v)
    if (count(v) > 0) order.push_back(v);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return count(a) > count(b); });
  std::vector<Lab> given = {toLab(stencilColour(0))};  // black stays 0's, present or not
  const auto nearest = [&](const Lab& c) {
    float d = std::numeric_limits<float>::infinity();
    for (const Lab& g : given) d = std::min(d, distance(c, g));
    return d;
  };
  for (const int v : order) {
    Rgb& c = colours[static_cast<std::size_t>(v)];
    Lab lab = toLab(c);
    if (nearest(lab) < kStencilDistinct) {
      float best = -1.0f;
      for (const Candidate& k : kCandidates)
        if (const float d = nearest(k.lab); d > best) best = d, c = k.rgb, lab = k.lab;
    }
    given.push_back(lab);
  }
  return colours;
}

StencilLegend stencilLegend(const Image& stencil, bool grey) {
  StencilLegend legend;
  for (std::uint8_t v : stencil.pixels) ++legend.histogram[v];
  legend.colours = stencilPictureColours(legend.histogram);
  // The grey view stretches the values present so that the largest is white: counts of 0 to 7
  // would be black to the eye as grey levels 0 to 7. The legend starts with the rule.
  int largest = 0;
  for (int v = 0; v < 256; ++v)
    if (legend.histogram[static_cast<std::size_t>(v)] > 0) largest = v;
  if (grey) {
    legend.greyRule = "v x 255/" + std::to_string(largest);
    for (int v = 0; v < 256; ++v) {
      const auto g = static_cast<std::uint8_t>(largest > 0 ? std::min(255, (v * 255 + largest / 2) / largest) : 0);
      legend.colours[static_cast<std::size_t>(v)] = {g, g, g};
    }
  }
  return legend;
}

Image stencilRamp(const Image& stencil, const StencilRampStyle& style) {
  const StencilLegend legend = stencilLegend(stencil, style.grey);
  const std::vector<std::uint64_t>& histogram = legend.histogram;
  const std::array<Rgb, 256>& colours = legend.colours;
  const std::string& greyRule = legend.greyRule;

  const int k = std::max(style.legendScale, 1);
  const int scale = style.textPixels > 0 ? style.textPixels : 2 * k, small = scale,
            entryHeight = 7 * scale + 4 * k, swatch = 5 * scale, gap = 3 * k;
  const Rgb countGrey = style.textPixels > 0 ? Rgb{235, 235, 235} : Rgb{170, 170, 170};
  // Lay the legend entries out first to know how tall the band is. With a row limit, the lowest
  // values are kept, none skipped, and the rest counted in a "+N" entry.
  std::vector<int> shown;
  for (int v = 0; v < 256; ++v)
    if (histogram[static_cast<size_t>(v)] > 0) shown.push_back(v);
  struct Entry {
    int value, x, y;  // value -1: the "+N" of the values left out; -2: the grey view's rule
  };
  const auto entryWidth = [&](int v, int left) {
    return v == -2  ? textWidth(greyRule, scale) + 10 * k
           : v < 0 ? textWidth("+" + std::to_string(left), scale) + 10 * k
                 : swatch + gap + textWidth(std::to_string(v), scale) + gap +
                       textWidth("(" + std::to_string(histogram[static_cast<size_t>(v)]) + ")", small) + 10 * k;
  };
  std::vector<Entry> entries;
  int rows = 1;
  const auto layout = [&](const std::vector<int>& values, int left) {
    entries.clear();
    int x = 4 * k, y = 4 * k;
    rows = 1;
    std::vector<int> all = values;
    if (style.grey) all.insert(all.begin(), -2);
    if (left > 0) all.push_back(-1);
    for (const int v : all) {
      const int width = entryWidth(v, left);
      if (x + width > stencil.width && x > 4 * k) x = 4 * k, y += entryHeight, ++rows;
      entries.push_back({v, x, y});
      x += width;
    }
  };
  layout(shown, 0);
  if (style.maxLegendRows > 0 && rows > style.maxLegendRows) {
    // Drop the highest values one at a time until the rest and their "+N" fit: a legend read in
    // value order that skipped values (the rarest) would look like values missing from the picture.
    std::vector<int> kept = shown;
    while (!kept.empty()) {
      kept.pop_back();
      layout(kept, static_cast<int>(shown.size() - kept.size()));
      if (rows <= style.maxLegendRows) break;
    }
  }
  const int band = style.legend ? entries.back().y + entryHeight : 0;

  Image out(stencil.width, stencil.height + band, 4);
  for (int py = 0; py < stencil.height; ++py)
    for (int px = 0; px < stencil.width; ++px) fillRect(out, px, py, 1, 1, colours[*stencil.at(px, py)]);
  // A value a handful of pixels hold would be lost among the others: a ring in its colour, 4 pixels
  // out, around each of its pixels, drawn only over pixels of other values.
  for (int py = 0; py < stencil.height && !style.grey; ++py)
    for (int px = 0; px < stencil.width; ++px) {
      const std::uint8_t v = *stencil.at(px, py);
      if (histogram[v] >= kRarePixels) continue;
      for (int d = -4; d <= 4; ++d)
        for (const auto& [rx, ry] : {std::pair{px + d, py - 4}, std::pair{px + d, py + 4},
                                     std::pair{px - 4, py + d}, std::pair{px + 4, py + d}})
          if (rx >= 0 && ry >= 0 && rx < stencil.width && ry < stencil.height && *stencil.at(rx, ry) != v)
            fillRect(out, rx, ry, 1, 1, colours[v]);
    }
  if (!style.legend) return out;
  fillRect(out, 0, stencil.height, out.width, band, {48, 48, 48});
  for (const Entry& e : entries) {
    const int top = stencil.height + e.y;
    if (e.value == -2) {
      drawText(out, e.x, top, greyRule, scale, {255, 255, 255});
      continue;
    }
    if (e.value < 0) {
      drawText(out, e.x, top, "+" + std::to_string(shown.size() + (style.grey ? 2 : 1) - entries.size()), scale,
               {255, 255, 255});
      continue;
    }
    fillRect(out, e.x - 1, top - 1, swatch + 2, swatch + 2, {200, 200, 200});  // outline: 0 is black
    fillRect(out, e.x, top, swatch, swatch, colours[static_cast<std::size_t>(e.value)]);
    const int numberX = e.x + swatch + gap;
    drawNumber(out, numberX, top, e.value, scale, {255, 255, 255});
    const std::string n = "(" + std::to_string(histogram[static_cast<std::size_t>(e.value)]) + ")";
    drawText(out, numberX + textWidth(std::to_string(e.value), scale) + gap, top + 5 * scale - 5 * small, n,
             small, countGrey);
  }
  return out;
}

Rgb countColour(int count, int top) {
  // Anchors of rising luminance (about 31, 59, 86, 133, 192, 245): interpolating linearly between
  // them keeps it rising, since luminance is linear in the channels.
  static constexpr std::array<std::array<float, 3>, 6> kRamp = {
      {{40, 20, 110}, {120, 30, 160}, {200, 50, 110}, {240, 110, 40}, {250, 190, 40}, {250, 250, 180}}};
  if (count <= 0) return {0, 0, 0};
  top = std::max(top, 1);
  const float t =
      top == 1 ? 1.0f : static_cast<float>(std::min(count, top) - 1) / static_cast<float>(top - 1);
  const float at = t * static_cast<float>(kRamp.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(at), kRamp.size() - 2);
  const float f = at - static_cast<float>(i);
  Rgb c;
  for (std::size_t k = 0; k < 3; ++k)
    c[k] = static_cast<std::uint8_t>(std::lround(kRamp[i][k] + f * (kRamp[i + 1][k] - kRamp[i][k])));
  return c;
}

Rgb saturatedCountColour() {
  return {0, 220, 255};
}

float luminance(const Rgb& c) {
  return 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
}

Image countLegend(const std::vector<std::uint64_t>& histogram, int top, bool saturated, int width,
                  const std::function<std::string(int)>& label, int textScale) {
  top = std::max(top, 1);
  const int scale = textScale > 0 ? textScale : width >= 480 ? 2 : 1, margin = 3 * scale, barHeight = 16 * scale, strip = 4 * scale,
            text = 5 * scale;
  const int height = margin + barHeight + strip + 2 * scale + text + margin;
  Image out(std::max(width, 1), height, 4);
  fillRect(out, 0, 0, out.width, out.height, {48, 48, 48});
  const auto pixels = [&](int k) {
    return static_cast<std::size_t>(k) < histogram.size() ? histogram[static_cast<std::size_t>(k)] : 0;
  };
  std::uint64_t most = 1;
  for (int k = 0; k <= top; ++k) most = std::max(most, pixels(k));
  if (saturated) most = std::max(most, pixels(255));
  // The saturated column sits apart at the right, as wide as its label.
  const int satWidth = saturated ? textWidth("255+", scale) + 2 * scale : 0;
  const int x0 = margin, x1 = out.width - margin - (saturated ? satWidth + 3 * margin : 0);
  const int columns = top + 1;
  const auto columnX = [&](int k) { return x0 + (x1 - x0) * k / columns; };
  const int stripTop = margin + barHeight, labelTop = stripTop + strip + 2 * scale;
  const auto column = [&](int left, int right, std::uint64_t n, Rgb c) {
    // A bar for every count present, at least a pixel tall, on a log scale: a count a handful of
    // pixels have still shows beside one that most have.
    const int bar =
        n == 0 ? 0
               : std::max(1, static_cast<int>(std::lround(barHeight * std::log1p(static_cast<double>(n)) /
                                                          std::log1p(static_cast<double>(most)))));
    fillRect(out, left, stripTop - bar, right - left, bar, c);
    fillRect(out, left, stripTop, right - left, strip, c);
  };
  for (int k = 0; k <= top; ++k)
    column(columnX(k), std::max(columnX(k + 1), columnX(k) + 1), pixels(k), countColour(k, top));
  fillRect(out, x0, stripTop + strip, x1 - x0, 1, {200, 200, 200});
  // Labels: top always, and the multiples of a round step (1, 2, 5, 10, 20, 50, 100) far enough
  // apart to read, dropping those that would touch top's.
  const auto labelLeft = [&](int k) {
    const std::string labelText = label(k);
    const int centre = (columnX(k) + std::max(columnX(k + 1), columnX(k) + 1)) / 2;
    return std::clamp(centre - textWidth(labelText, scale) / 2, 0, out.width - textWidth(labelText, scale));
  };
  const int widest = textWidth(label(top), scale) + 3 * scale;
  int step = 1;
  for (const int s : {1, 2, 5, 10, 20, 50, 100, 200}) {
    step = s;
    if (columnX(s) - columnX(0) >= widest) break;
  }
  const int topLeft = labelLeft(top);
  drawText(out, topLeft, labelTop, label(top), scale, {255, 255, 255});
  for (int k = 0; k < top; k += step) {
    const int left = labelLeft(k);
    if (left + textWidth(label(k), scale) + 2 * scale > topLeft) break;
    drawText(out, left, labelTop, label(k), scale, {255, 255, 255});
  }
  if (saturated) {
    const int left = out.width - margin - satWidth;
    column(left, left + satWidth, pixels(255), saturatedCountColour());
    drawText(out, left + scale, labelTop, "255+", scale, saturatedCountColour());
  }
  return out;
}

Image countLegend(const std::vector<std::uint64_t>& histogram, int top, bool saturated, int width,
                  int textScale) {
  return countLegend(
      histogram, top, saturated, width, [](int k) { return std::to_string(k); }, textScale);
}

Image countPicture(const Image& stencil, bool saturates) {
  std::vector<std::uint64_t> histogram(256, 0);
  for (std::uint8_t v : stencil.pixels) ++histogram[v];
  int top = 1;
  for (int k = 1; k < 256; ++k)
    if (histogram[static_cast<std::size_t>(k)] > 0 && !(saturates && k == 255)) top = k;
  const bool saturated = saturates;
  const Image legend = countLegend(histogram, top, saturated, stencil.width);
  Image out(stencil.width, stencil.height + legend.height, 4);
  for (int py = 0; py < stencil.height; ++py)
    for (int px = 0; px < stencil.width; ++px) {
      const int v = *stencil.at(px, py);
      fillRect(out, px, py, 1, 1, saturates && v == 255 ? saturatedCountColour() : countColour(v, top));
    }
  for (int py = 0; py < legend.height; ++py)
    std::copy_n(legend.at(0, py), 4 * legend.width, out.at(0, stencil.height + py));
  return out;
}

Image stencilBitPlanes(const Image& stencil, float labelScale) {
  const int w = stencil.width, h = stencil.height, gap = 2;
  Image out(4 * w + 3 * gap, 2 * h + gap, 4);
  fillRect(out, 0, 0, out.width, out.height, {128, 128, 128});
  for (int bit = 0; bit < 8; ++bit) {
    const int ox = (bit % 4) * (w + gap), oy = (bit / 4) * (h + gap);
    for (int py = 0; py < h; ++py)
      for (int px = 0; px < w; ++px) {
        const bool set = (*stencil.at(px, py) >> bit) & 1u;
        fillRect(out, ox + px, oy + py, 1, 1, set ? Rgb{255, 255, 255} : Rgb{0, 0, 0});
      }
    // The label grows with the tile: the window shows the eight tiles at a quarter of their size.
    const int scale = std::max(2, static_cast<int>(std::lround(static_cast<float>(w / 64) * labelScale)));
    fillRect(out, ox + scale, oy + scale, 5 * scale, 7 * scale, {200, 40, 40});
    drawNumber(out, ox + 2 * scale, oy + 2 * scale, bit, scale, {255, 255, 255});
  }
  return out;
}

std::string hoursAndMinutes(int minutes) {
  const int m = minutes % 60;
  return std::to_string(minutes / 60) + "h" + (m == 0 ? "" : (m < 10 ? "0" : "") + std::to_string(m));
}

Image shadowHoursPicture(const std::vector<std::uint16_t>& counts, int width, int height, int steps,
                         int stepMinutes) {
  const int top = std::max(1, steps);
  std::vector<std::uint64_t> histogram(static_cast<std::size_t>(top) + 1, 0);
  Image map(width, height, 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int k = std::min<int>(counts[static_cast<std::size_t>(y) * width + x], top);
      ++histogram[static_cast<std::size_t>(k)];
      const Rgb c = countColour(k, top);
      std::uint8_t* p = map.at(x, y);
      p[0] = c[0], p[1] = c[1], p[2] = c[2], p[3] = 255;
    }
  const auto hours = [stepMinutes](int k) { return hoursAndMinutes(k * stepMinutes); };
  const Image legend = countLegend(histogram, top, false, width, hours);
  Image out(width, height + legend.height, 4);
  std::copy(map.pixels.begin(), map.pixels.end(), out.pixels.begin());
  std::copy(legend.pixels.begin(), legend.pixels.end(), out.pixels.begin() + map.pixels.size());
  return out;
}

float eyeDepth(float windowDepth, const glm::mat4& projection, bool reversed) {
  const float ndc = reversed ? 1.0f - 2.0f * windowDepth : 2.0f * windowDepth - 1.0f;
  // clip z = P22 z + P32, clip w = P23 z + P33 (glm: [column][row]); ndc = clip z / clip w.
  const float denominator = ndc * projection[2][3] - projection[2][2];
  if (denominator == 0.0f) return std::numeric_limits<float>::infinity();
  return -(projection[3][2] - ndc * projection[3][3]) / denominator;
}

Image depthPicture(const std::vector<float>& depth, int width, int height, const glm::mat4& projection,
                   bool reversed, DepthRange* rangeOut, int textScale, bool window) {
  std::vector<float> eye(depth.size());
  DepthRange range;
  range.nearest = std::numeric_limits<float>::infinity();
  range.farthest = -std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < depth.size(); ++i) {
    const bool cleared = reversed ? depth[i] <= 0.0f : depth[i] >= 1.0f;
    eye[i] = cleared ? std::numeric_limits<float>::quiet_NaN() : eyeDepth(depth[i], projection, reversed);
    if (!std::isfinite(eye[i])) {
      eye[i] = std::numeric_limits<float>::quiet_NaN();
      ++range.cleared;
      continue;
    }
    ++range.drawn;
    range.nearest = std::min(range.nearest, eye[i]);
    range.farthest = std::max(range.farthest, eye[i]);
  }
  if (range.drawn == 0) range.nearest = range.farthest = 0.0f;
  const float span = range.farthest - range.nearest;
  const auto grey = [&](float t) {  // t: 0 nearest .. 1 farthest
    const auto g = static_cast<std::uint8_t>(std::lround(255.0f - t * (255.0f - kDepthFarGrey)));
    return Rgb{g, g, g};
  };

  const int scale = std::max(1, textScale), small = scale, band = 7 * scale + 8;
  Image out(width, height + band, 4);
  for (int py = 0; py < height; ++py)
    for (int px = 0; px < width; ++px) {
      const float e = eye[static_cast<std::size_t>(py) * static_cast<std::size_t>(width) + px];
      fillRect(out, px, py, 1, 1,
               std::isnan(e) ? kDepthClearedColour : grey(span > 0.0f ? (e - range.nearest) / span : 0.0f));
    }
  fillRect(out, 0, height, width, band, {48, 48, 48});
  char nearText[32], farText[32];
  std::snprintf(nearText, sizeof nearText, "%.2f", static_cast<double>(range.nearest));
  std::snprintf(farText, sizeof farText, "%.2f", static_cast<double>(range.farthest));
  const std::string clearedText = (window ? "far (" : "(") + std::to_string(range.cleared) + ")";
  const int top = height + 4, swatch = 5 * scale;
  // The ramp between the two eye depths, then the cleared swatch and its count at the right.
  const int clearedWidth = swatch + 3 + textWidth(clearedText, small) + 4;
  int x = 4;
  x += drawText(out, x, top, nearText, scale, {255, 255, 255}) + 3;
  const int rampEnd = width - clearedWidth - textWidth(farText, scale) - 10;
  for (int rx = x; rx < rampEnd; ++rx)
    fillRect(out, rx, top, 1, swatch,
             grey(static_cast<float>(rx - x) / static_cast<float>(std::max(1, rampEnd - x - 1))));
  x = std::max(x, rampEnd) + 3;
  x += drawText(out, x, top, farText, scale, {255, 255, 255}) + 6;
  fillRect(out, x - 1, top - 1, swatch + 2, swatch + 2, {200, 200, 200});
  fillRect(out, x, top, swatch, swatch, kDepthClearedColour);
  drawText(out, x + swatch + 3, top + 5 * scale - 5 * small, clearedText, small,
           window ? Rgb{235, 235, 235} : Rgb{170, 170, 170});
  if (rangeOut) *rangeOut = range;
  return out;
}

std::string depthLegendLine(const DepthRange& r) {
  std::ostringstream line;
  line.setf(std::ios::fixed);
  line.precision(2);
  if (r.drawn == 0) {
    line << "depth: nothing drawn; blue: the far plane or nothing drawn (" << r.cleared << " pixels)";
    return line.str();
  }
  line << "depth: eye depth " << r.nearest << " (white) to " << r.farthest
       << " (dark grey), stretched linearly over the depths present; blue: the far plane or nothing drawn ("
       << r.cleared << " pixels)";
  return line.str();
}

}  // namespace stencil
