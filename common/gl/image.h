// 8-bit images in memory, rows top to bottom, and PNG files (stb); output files written
// all or nothing.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
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

// Writes a PNG with writeFile. Throws OutputError (gl/errors.h) on failure.
void writePng(const std::filesystem::path&, const Image&);
// Reads a PNG with the given channel count (1 or 4). Throws std::runtime_error on failure.
Image readPng(const std::filesystem::path&, int channels);

// Writes `bytes` to `path` all or nothing, creating parent folders: into a temporary file beside
// it, every write and the close checked, then renamed onto it. Throws OutputError naming the path
// and the system's reason, the temporary removed.
void writeFile(const std::filesystem::path&, std::string_view bytes);

// Checks, without writing anything that stays, that writeFile could write a file at `path`: a
// name, not an existing folder or special file, in a folder that exists or can be made and
// takes new files. Throws OutputError "FLAG PATH: why".
void checkOutputFile(const std::filesystem::path&, const std::string& flag);
// The same for a folder that files will be written into: a folder or nothing there yet, in
// which new files can be made.
void checkOutputFolder(const std::filesystem::path&, const std::string& flag);

}  // namespace stencil
