#include "gl/golden.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "gl/stencil_view.h"

namespace stencil {
namespace {

// The actual image, greyed and dimmed, as the background of a diff picture.
Image dimmed(const Image& actual) {
  Image out(actual.width, actual.height, 4);
  for (int y = 0; y < actual.height; ++y)
    for (int x = 0; x < actual.width; ++x) {
      const std::uint8_t* a = actual.at(x, y);
      int grey = actual.channels == 1 ? a[0] : (a[0] + a[1] + a[2]) / 3;
      std::uint8_t v = static_cast<std::uint8_t>(grey / 4);
      std::uint8_t* o = out.at(x, y);
      o[0] = o[1] = o[2] = v, o[3] = 255;
    }
  return out;
}

void markRed(Image& picture, int x, int y) {
  std::uint8_t* o = picture.at(x, y);
  o[0] = 255, o[1] = 0, o[2] = 0;
}

// Compares the first `channels` channels of each pixel: a pixel differs when one of them is off by
// more than `allowed`; each differing pixel is marked red on a dimmed copy of `actual`.
ImageDiff diffImages(const Image& actual, const Image& expected, int channels, int allowed) {
  ImageDiff d;
  if (actual.width != expected.width || actual.height != expected.height) {
    d.sizeMismatch = true;
    return d;
  }
  d.picture = dimmed(actual);
  d.pixels = static_cast<std::uint64_t>(actual.width) * actual.height;
  for (int y = 0; y < actual.height; ++y)
    for (int x = 0; x < actual.width; ++x) {
      int worst = 0;
      for (int c = 0; c < channels; ++c)
        worst = std::max(worst, std::abs(actual.at(x, y)[c] - expected.at(x, y)[c]));
      d.maxChannelDiff = std::max(d.maxChannelDiff, worst);
      if (worst > allowed) {
        ++d.differing;
        markRed(d.picture, x, y);
      }
    }
  return d;
}

}  // namespace

ImageDiff diffColour(const Image& actual, const Image& expected, int maxChannelDiff) {
  return diffImages(actual, expected, 4, maxChannelDiff);
}

ImageDiff diffStencil(const Image& actual, const Image& expected) {
  return diffImages(actual, expected, 1, 0);
}

std::filesystem::path goldenColourPath(const std::filesystem::path& dir, const std::string& name) {
  return dir / (name + ".png");
}
std::filesystem::path goldenStencilPath(const std::filesystem::path& dir, const std::string& name) {
  return dir / (name + ".stencil.png");
}

GoldenResult checkGolden(const Image& colour, const Image& stencil, const std::filesystem::path& dir,
                         const std::string& name, const std::filesystem::path& artifacts, OutputSet& out,
                         const ColourTolerance& tolerance) {
  const auto colourPath = goldenColourPath(dir, name), stencilPath = goldenStencilPath(dir, name);
  if (!std::filesystem::exists(colourPath) || !std::filesystem::exists(stencilPath)) {
    out.addPng(artifacts / "colour-actual.png", colour);
    out.addPng(artifacts / "stencil-actual.raw.png", stencil);
    return {false, "no golden " + colourPath.string() + " / " + stencilPath.string() +
                       " (see docs/testing.md to create it)"};
  }
  const Image expectedColour = readPng(colourPath, 4), expectedStencil = readPng(stencilPath, 1);
  const ImageDiff c = diffColour(colour, expectedColour, tolerance.maxChannelDiff);
  const ImageDiff s = diffStencil(stencil, expectedStencil);
  if (c.sizeMismatch || s.sizeMismatch)
    return {false, "size " + std::to_string(colour.width) + "x" + std::to_string(colour.height) +
                       " differs from the golden's " + std::to_string(expectedColour.width) + "x" +
                       std::to_string(expectedColour.height)};

  const double fraction = static_cast<double>(c.differing) / static_cast<double>(c.pixels);
  const bool passed = s.differing == 0 && fraction <= tolerance.maxFraction;
  std::ostringstream msg;
  msg << "stencil: " << s.differing << " of " << s.pixels << " pixels differ; colour: " << c.differing
      << " pixels (" << fraction * 100 << "%) over " << tolerance.maxChannelDiff << "/255, max channel diff "
      << c.maxChannelDiff << ", allowed " << tolerance.maxFraction * 100 << "%";
  if (passed) return {true, msg.str()};

  out.addPng(artifacts / "colour-actual.png", colour);
  out.addPng(artifacts / "colour-expected.png", expectedColour);
  out.addPng(artifacts / "colour-diff.png", c.picture);
  out.addPng(artifacts / "stencil-actual.png", stencilRamp(stencil));
  out.addPng(artifacts / "stencil-expected.png", stencilRamp(expectedStencil));
  out.addPng(artifacts / "stencil-diff.png", s.picture);
  out.addPng(artifacts / "stencil-actual.raw.png", stencil);
  std::ostringstream json;
  json << "{\n  \"golden\": \"" << colourPath.string() << "\",\n"
       << "  \"passed\": false,\n"
       << "  \"stencil_pixels_differing\": " << s.differing << ",\n"
       << "  \"stencil_max_diff\": " << s.maxChannelDiff << ",\n"
       << "  \"colour_pixels_over_tolerance\": " << c.differing << ",\n"
       << "  \"colour_fraction_over_tolerance\": " << fraction << ",\n"
       << "  \"colour_max_channel_diff\": " << c.maxChannelDiff << ",\n"
       << "  \"tolerance\": {\"max_channel_diff\": " << tolerance.maxChannelDiff
       << ", \"max_fraction\": " << tolerance.maxFraction << "},\n"
       << "  \"pixels\": " << s.pixels << "\n}\n";
  out.add(artifacts / "summary.json", json.str());
  return {false, msg.str() + "; images and summary.json in " + artifacts.string()};
}

void writeGolden(const Image& colour, const Image& stencil, const std::filesystem::path& dir,
                 const std::string& name, OutputSet& out) {
  out.addPng(goldenColourPath(dir, name), colour);
  out.addPng(goldenStencilPath(dir, name), stencil);
}

bool isGoldenRenderer(const std::string& renderer) {
  return renderer.find("llvmpipe") != std::string::npos;
}

}  // namespace stencil
