// The stencil inspector: turns a stencil buffer (one byte per pixel) into a picture.
#pragma once
#include <array>
#include <cstdint>

#include "gl/image.h"

namespace stencil {

// The colour a stencil value is shown in: 0 black, 1..12 distinct hues, larger values on
// a ramp. The same value has the same colour in every picture.
std::array<std::uint8_t, 3> stencilColour(std::uint8_t value);

// Pseudo-colour picture with a legend band below: a swatch and the value for each value
// present, in ascending order.
Image stencilRamp(const Image& stencil);

// The eight bit planes side by side (4 x 2 tiles, bit 0 top left): white where set.
Image stencilBitPlanes(const Image& stencil);

}  // namespace stencil
