#include "gl/stencil_view.h"

#include <algorithm>
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

// Draws a number with the digit font scaled by `scale`; returns the width drawn.
int drawNumber(Image& img, int x, int y, int number, int scale, Rgb c) {
  const std::string text = std::to_string(number);
  for (size_t i = 0; i < text.size(); ++i) {
    const std::uint16_t glyph = kDigits[static_cast<size_t>(text[i] - '0')];
    for (int row = 0; row < 5; ++row)
      for (int col = 0; col < 3; ++col)
        if (glyph & (1u << (14 - (row * 3 + col))))
          fillRect(img, x + (static_cast<int>(i) * 4 + col) * scale, y + row * scale, scale, scale, c);
  }
  return static_cast<int>(text.size()) * 4 * scale;
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

}  // namespace stencil
