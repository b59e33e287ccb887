// figure_compare EXPECTED ACTUAL [--exact]: compares a committed page figure with a fresh render
// by the golden tests' rule (gl/golden.h): a pixel differs when a channel differs by more than
// 5/255, and at most 0.1% of the pixels may differ; with --exact (stencil pictures, raw stencil
// values) no pixel may differ at all. Both files are read as RGBA (a grey PNG's value in R, G, B).
// Prints one line; exit 0 when they agree, 1 when they do not, 2 when a file cannot be read.
#include <cstdio>
#include <exception>
#include <string>

#include "gl/golden.h"
#include "gl/image.h"

int main(int argc, char** argv) {
  const bool exact = argc == 4 && std::string(argv[3]) == "--exact";
  if (argc != 3 && !exact) {
    std::fprintf(stderr, "usage: figure_compare EXPECTED.png ACTUAL.png [--exact]\n");
    return 2;
  }
  stencil::Image expected, actual;
  try {
    expected = stencil::readPng(argv[1], 4);
    actual = stencil::readPng(argv[2], 4);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "figure_compare: %s\n", e.what());
    return 2;
  }
  const stencil::ColourTolerance tolerance;
  const stencil::ImageDiff d = stencil::diffColour(actual, expected, exact ? 0 : tolerance.maxChannelDiff);
  if (d.sizeMismatch) {
    std::printf("size %dx%d, committed %dx%d\n", actual.width, actual.height, expected.width, expected.height);
    return 1;
  }
  const double fraction = static_cast<double>(d.differing) / static_cast<double>(d.pixels);
  const bool same = exact ? d.differing == 0 : fraction <= tolerance.maxFraction;
  std::printf("%llu of %llu pixels differ (%s), by up to %d levels\n",
              static_cast<unsigned long long>(d.differing), static_cast<unsigned long long>(d.pixels),
              exact ? "exact" : "over 5 levels, 0.1% allowed", d.maxChannelDiff);
  return same ? 0 : 1;
}
