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

// The goldens are Mesa llvmpipe's pictures (deterministic, on every machine CI runs on). A GPU
// rasterises shared edges, z-fighting and 8-bit blending its own way and has depth bounds
// llvmpipe lacks: on an NVIDIA H200, 47 of 270 EGL goldens differ, most by 1-7 stencil pixels at
// volume edges (docs/testing.md). Other renderers are checked by the ray-cast oracle instead.
// renderer: GL_RENDERER.
bool isGoldenRenderer(const std::string& renderer);

struct GoldenResult {
  bool passed = false;
  std::string message;  // one line
};

// Paths of a golden pair: <dir>/<name>.png (colour) and <dir>/<name>.stencil.png (raw values).
std::filesystem::path goldenColourPath(const std::filesystem::path& dir, const std::string& name);
std::filesystem::path goldenStencilPath(const std::filesystem::path& dir, const std::string& name);

// Compares; on failure stages actual, expected and diff PNGs and summary.json under `artifacts`
// in `out` (written when the caller commits it).
GoldenResult checkGolden(const Image& colour, const Image& stencil, const std::filesystem::path& dir,
                         const std::string& name, const std::filesystem::path& artifacts, OutputSet& out,
                         const ColourTolerance& = {});
// Stages the golden pair in `out`.
void writeGolden(const Image& colour, const Image& stencil, const std::filesystem::path& dir,
                 const std::string& name, OutputSet& out);

}  // namespace stencil
