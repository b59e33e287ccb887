#include "gl/stencil_view.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

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
constexpr std::uint16_t kPoint = 0b000'000'000'000'010;
constexpr std::uint16_t kHour = 0b100'100'111'101'101;  // 'h'

// Draws digits, '+', '.' and 'h' with the font scaled by `scale`; returns the width drawn.
int drawText(Image& img, int x, int y, const std::string& text, int scale, Rgb c) {
  for (size_t i = 0; i < text.size(); ++i) {
    const std::uint16_t glyph = text[i] == '+'   ? kPlus
                                : text[i] == '.' ? kPoint
                                : text[i] == 'h' ? kHour
                                                 : kDigits[static_cast<size_t>(text[i] - '0')];
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
  // 13..255: from dark violet to white. Red is the value itself, so no two values share a colour.
  const float t = static_cast<float>(value - 13) / (255.0f - 13.0f);
  return {value, static_cast<std::uint8_t>(40 + 215 * t), static_cast<std::uint8_t>(140 + 115 * t)};
}

Image stencilRamp(const Image& stencil) {
  std::array<bool, 256> present{};
  for (std::uint8_t v : stencil.pixels) present[v] = true;

  const int scale = 2, entryHeight = 7 * scale + 4, swatch = 5 * scale;
  // Lay the legend entries out first to know how tall the band is.
  struct Entry {
    int value, x, y;
  };
  std::vector<Entry> entries;
  int x = 4, y = 4;
  for (int v = 0; v < 256; ++v) {
    if (!present[static_cast<size_t>(v)]) continue;
    const int width = swatch + 3 + static_cast<int>(std::to_string(v).size()) * 4 * scale + 8;
    if (x + width > stencil.width && x > 4) x = 4, y += entryHeight;
    entries.push_back({v, x, y});
    x += width;
  }
  const int band = y + entryHeight;

  Image out(stencil.width, stencil.height + band, 4);
  for (int py = 0; py < stencil.height; ++py)
    for (int px = 0; px < stencil.width; ++px) {
      const Rgb c = stencilColour(*stencil.at(px, py));
      fillRect(out, px, py, 1, 1, c);
    }
  fillRect(out, 0, stencil.height, out.width, band, {48, 48, 48});
  for (const Entry& e : entries) {
    const int top = stencil.height + e.y;
    fillRect(out, e.x - 1, top - 1, swatch + 2, swatch + 2, {200, 200, 200});  // outline: 0 is black
    fillRect(out, e.x, top, swatch, swatch, stencilColour(static_cast<std::uint8_t>(e.value)));
    drawNumber(out, e.x + swatch + 3, top, e.value, scale, {255, 255, 255});
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
                  const std::function<std::string(int)>& label) {
  top = std::max(top, 1);
  const int scale = width >= 480 ? 2 : 1, margin = 3 * scale, barHeight = 16 * scale, strip = 4 * scale,
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

Image countLegend(const std::vector<std::uint64_t>& histogram, int top, bool saturated, int width) {
  return countLegend(histogram, top, saturated, width, [](int k) { return std::to_string(k); });
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

Image stencilBitPlanes(const Image& stencil) {
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
    fillRect(out, ox + 2, oy + 2, 4 * 2 + 4, 5 * 2 + 4, {200, 40, 40});
    drawNumber(out, ox + 4, oy + 4, bit, 2, {255, 255, 255});
  }
  return out;
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
  // Hours with one decimal where a step is not a whole number of hours.
  const auto hours = [stepMinutes](int k) {
    const int tenths = static_cast<int>(std::lround(k * stepMinutes / 6.0));
    return std::to_string(tenths / 10) + (tenths % 10 ? "." + std::to_string(tenths % 10) : "") + "h";
  };
  const Image legend = countLegend(histogram, top, false, width, hours);
  Image out(width, height + legend.height, 4);
  std::copy(map.pixels.begin(), map.pixels.end(), out.pixels.begin());
  std::copy(legend.pixels.begin(), legend.pixels.end(), out.pixels.begin() + map.pixels.size());
  return out;
}

}  // namespace stencil
