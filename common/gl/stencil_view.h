// The stencil inspector: turns a stencil buffer (one byte per pixel) into a picture.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "gl/image.h"

namespace stencil {

// The colour a stencil value is shown in: 0 black, 1..12 twelve distinct hues, 13..255 hues a
// golden angle (137.5 degrees) apart at three lightnesses in turn, so that neighbouring values
// (13 and 14, 128 and 129) never look alike. Lessons that colour stencil values themselves use it,
// so the lesson's picture and the stencil picture speak one colour language.
std::array<std::uint8_t, 3> stencilColour(std::uint8_t value);

// How far apart two colours look: the CIE76 colour difference (Euclidean distance in CIELAB,
// D65 white) of two sRGB byte triples. About 2.3 is just noticeable; kStencilDistinct apart,
// two flat regions side by side read as different colours at a glance, on a projector too (25
// apart, values of a 21-value picture looked alike there).
float colourDistance(const std::array<std::uint8_t, 3>&, const std::array<std::uint8_t, 3>&);
constexpr float kStencilDistinct = 35.0f;

// The colours one stencil picture gives its values, histogram[v] pixels holding v (256 entries):
// each present value keeps stencilColour(v) unless that lies within kStencilDistinct of black or
// of a colour already given (values taken 0 first, then by pixel count, most first); such a value
// gets the sRGB colour (channels multiples of 255/11) farthest from all those already given. Up to
// 24 present values are all kStencilDistinct apart (tests/unit/test_stencil_view.cpp). Values not
// present get their stencilColour.
std::array<std::array<std::uint8_t, 3>, 256> stencilPictureColours(
    const std::vector<std::uint64_t>& histogram);

// Pseudo-colour picture in stencilPictureColours with a legend band below: for each value present,
// in ascending order, a swatch, the value and (in brackets, grey) its pixel count. A value held by
// fewer than kRarePixels pixels is pointed at: a ring in its colour around each of its pixels.
constexpr std::uint64_t kRarePixels = 16;
// How the window draws it (the defaults are the headless pictures'): the legend's digits and
// swatches legendScale times their size; at most maxLegendRows rows of entries (0: as many as
// the values need), the lowest values kept and the others counted as "+N" at the end; or no
// legend band at all (the window's panel lists the values instead). `grey`: each value v in grey
// v x 255 / top, top the largest value present (0 black, top white; the raw values are
// --stencil-out's), no rings, the legend starting with that rule ("v x 255/7"). textPixels > 0 (the
// window's): the legend's digits and counts that many pixels a dot, the counts near-white.
struct StencilRampStyle {
  int legendScale = 1;
  int maxLegendRows = 0;
  bool legend = true;
  bool grey = false;
  int textPixels = 0;
};
Image stencilRamp(const Image& stencil, const StencilRampStyle& style = {});
// What stencilRamp's legend lists: each value's pixel count (256 entries) and colour in the
// picture (stencilPictureColours, or with `grey` the grey view's v x 255 / top), and the grey
// view's rule ("v x 255/7"; empty without `grey`). The browser's page lists it below the canvas.
struct StencilLegend {
  std::vector<std::uint64_t> histogram = std::vector<std::uint64_t>(256, 0);
  std::array<std::array<std::uint8_t, 3>, 256> colours{};
  std::string greyRule;
};
StencilLegend stencilLegend(const Image& stencil, bool grey);

// The eight bit planes side by side (4 x 2 tiles, bit 0 top left): white where set, each tile
// labelled with its bit in digits 1/64 of the tile's width wide times labelScale (the window's
// UI scale), at least 2 pixels a dot.
Image stencilBitPlanes(const Image& stencil, float labelScale = 1.0f);

// Depth complexity's colours (lesson 13): a count of 0 is black, 1..top run along one ramp from
// dark indigo through crimson and orange to pale yellow whose luminance rises with the count, so a
// larger count always looks brighter; counts above top show as top. The saturated count (255 for a
// stencil that stops there, INCR) has a colour of its own off the ramp, cyan: "this many or more".
// top >= 1.
std::array<std::uint8_t, 3> countColour(int count, int top);
std::array<std::uint8_t, 3> saturatedCountColour();
// Rec. 709 luminance of an sRGB byte triple, 0..255 (the ramp's monotone measure).
float luminance(const std::array<std::uint8_t, 3>&);

// The legend of a count picture as a band `width` pixels wide: for every count 0..top a column in
// its colour, a bar above it for its pixels (histogram[k] pixels have count k) on a log scale, the
// tallest the most common count, the counts written under the columns (as many as fit,
// 0 and top always), and, when `saturated` is set, a cyan column apart labelled "255+" with its own
// bar (histogram[255]). top is the largest count in the ramp; histogram has 256 entries or fewer.
// Its digits are 1 pixel a dot below 480 pixels wide, else 2; textScale > 0 gives the pixels a dot
// (the window's UI scale).
Image countLegend(const std::vector<std::uint64_t>& histogram, int top, bool saturated, int width,
                  int textScale = 0);
// The same with each column's label given: label(k) for count k (digits, '+', '.' and 'h').
Image countLegend(const std::vector<std::uint64_t>& histogram, int top, bool saturated, int width,
                  const std::function<std::string(int)>& label, int textScale = 0);

// A stencil of counts as a picture: each value in countColour (255 in cyan when `saturates`), the
// ramp's top the largest value present (other than a saturated 255), and countLegend below.
Image countPicture(const Image& stencil, bool saturates);

// A shadow-hours map (--shadow-hours): counts[i] is how many of `steps` sun positions above the
// horizon (the daylight steps; night is not shadow), stepMinutes apart, left pixel i (top row
// first, width x height) in shadow. Each pixel in
// countColour(count, steps), and below, countLegend labelled in hours (hoursAndMinutes of
// count x stepMinutes).
// A legend's label for a span of time, exact in the legend's few glyphs: "3h" on the hour, else
// hours and two digits of minutes ("1h20", "0h05"). minutes >= 0.
std::string hoursAndMinutes(int minutes);

Image shadowHoursPicture(const std::vector<std::uint16_t>& counts, int width, int height, int steps,
                         int stepMinutes);

// The depth view. The eye depth (distance along the view direction, eye units) of a window depth
// d in [0, 1] under `projection`, given in GL's convention (Frame::projection): normalised z is
// 2d - 1, or 1 - 2d for reversed depth (geometry/projection.h), solved for eye z on the view axis.
// Perspective (finite or infinite far plane) or parallel. Infinity at the infinite far plane.
float eyeDepth(float windowDepth, const glm::mat4& projection, bool reversed);

// What a depth picture shows: the nearest and farthest eye depth present (not counting cleared
// pixels), and how many pixels hold the cleared depth (1, or 0 for reversed depth: the far plane
// or nothing drawn).
struct DepthRange {
  float nearest = 0.0f, farthest = 0.0f;
  std::uint64_t cleared = 0, drawn = 0;
};

// The depth buffer (window depths, width x height, top row first) as a picture: each drawn pixel
// grey by its eye depth, the range of eye depths present stretched linearly from white (nearest,
// 255) to dark grey (farthest, kDepthFarGrey), so a scene's depth reads whatever its near and far
// planes; the cleared depth in kDepthClearedColour. Reversed depth gives the picture standard depth
// gives for the same eye depths. Below, a legend band: the ramp with the nearest and farthest eye
// depth written at its ends (2 decimals), and a swatch of the cleared colour with its pixel count,
// its digits textScale pixels a dot (2; the window's follow its UI scale). `window`: the cleared
// swatch labelled "far" (the far plane or nothing drawn) and its count near-white.
constexpr std::uint8_t kDepthFarGrey = 48;
constexpr std::array<std::uint8_t, 3> kDepthClearedColour = {20, 40, 120};
Image depthPicture(const std::vector<float>& depth, int width, int height, const glm::mat4& projection,
                   bool reversed, DepthRange* range = nullptr, int textScale = 2, bool window = false);
// One line for a terminal: the range a depth picture stretched, and what its colours mean.
std::string depthLegendLine(const DepthRange&);

}  // namespace stencil
