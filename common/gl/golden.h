// Golden images: the stencil buffer must match exactly, the colour image within a
// tolerance (software rasterisers and GPUs differ in the last bit of shading).
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>

#include "gl/image.h"

namespace stencil {

// A colour pixel differs when any channel differs by more than maxChannelDiff; the image
// passes when at most maxFraction of its pixels differ.
struct ColourTolerance {
  int maxChannelDiff = 5;
  double maxFraction = 0.001;
};

struct ImageDiff {
  std::uint64_t pixels = 0;
  std::uint64_t differing = 0;  // pixels over tolerance (stencil: any difference)
  int maxChannelDiff = 0;
  bool sizeMismatch = false;
  Image picture;  // the actual image dimmed, differing pixels in red
};

ImageDiff diffColour(const Image& actual, const Image& expected, int maxChannelDiff);
ImageDiff diffStencil(const Image& actual, const Image& expected);

struct GoldenResult {
  bool passed = false;
  std::string message;  // one line
};

// Paths of a golden pair: <dir>/<name>.png (colour) and <dir>/<name>.stencil.png (raw values).
std::filesystem::path goldenColourPath(const std::filesystem::path& dir, const std::string& name);
std::filesystem::path goldenStencilPath(const std::filesystem::path& dir, const std::string& name);

// Compares; on failure writes actual, expected and diff PNGs and summary.json to artifacts.
GoldenResult checkGolden(const Image& colour, const Image& stencil, const std::filesystem::path& dir,
                         const std::string& name, const std::filesystem::path& artifacts,
                         const ColourTolerance& = {});
void writeGolden(const Image& colour, const Image& stencil, const std::filesystem::path& dir,
                 const std::string& name);

}  // namespace stencil
