// 8-bit images in memory, rows top to bottom, and PNG files (stb).
#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

namespace stencil {

struct Image {
  int width = 0, height = 0;
  int channels = 0;  // 1 (stencil values, grey) or 4 (RGBA)
  std::vector<std::uint8_t> pixels;

  Image() = default;
  Image(int w, int h, int c) : width(w), height(h), channels(c), pixels(static_cast<size_t>(w) * h * c) {}
  std::uint8_t* at(int x, int y) { return &pixels[(static_cast<size_t>(y) * width + x) * channels]; }
  const std::uint8_t* at(int x, int y) const {
    return &pixels[(static_cast<size_t>(y) * width + x) * channels];
  }
};

// Writes a PNG, creating parent folders. Throws std::runtime_error on failure.
void writePng(const std::filesystem::path&, const Image&);
// Reads a PNG with the given channel count (1 or 4). Throws std::runtime_error on failure.
Image readPng(const std::filesystem::path&, int channels);

}  // namespace stencil
