// Threshold patterns for a stencil dissolve (Kilgard, "Improving Shadows and Reflections via the
// Stencil Buffer", section 7), with no OpenGL: one 8-bit value per pixel, and a pixel shows the
// second scene at dissolve state k (0..256) when its value is below k. White noise, an ordered
// (Bayer) dither, blue noise by void-and-cluster (Ulichney, "The void-and-cluster method for
// dither array generation", SPIE 1913, 1993), and wipes; and the measures that tell them apart.
//
// Every image here is row-major, width * height values, row 0 at the bottom (GL's window
// coordinates: pixel (x, y) has its centre at (x + 0.5, y + 0.5)).
#pragma once
#include <cstdint>
#include <string_view>
#include <vector>

namespace stencil {

// The kinds of threshold pattern. Painted is not made here: a lesson sprays it into the stencil.
enum class PatternKind { WhiteNoise, Bayer, BlueNoise, LinearWipe, RadialWipe, ClockWipe };
const char* patternName(PatternKind);

// The ordered-dither (Bayer) index matrix of side 2^log2Side: each of 0..side*side-1 once,
// built by M(2n) = [[4M, 4M+2], [4M+3, 4M+1]] from M(1) = [0]. Row 0 first as above.
// Throws std::invalid_argument unless 0 <= log2Side <= 8.
std::vector<std::uint32_t> bayerMatrix(int log2Side);

// A blue-noise rank matrix of side `side` by void-and-cluster: each of 0..side*side-1 once, the
// pixels ranked so that those below any rank lie as evenly as they can (their largest void is
// filled first). Energy: a Gaussian of `sigma` pixels on the torus, so the tile repeats without
// seams. Deterministic: the initial pattern comes from `seed` through a fixed hash, ties go to
// the lowest index. O(side^4) time: about 0.1 s for side 64. Throws std::invalid_argument
// unless 2 <= side <= 256 and sigma > 0.
std::vector<std::uint32_t> voidAndCluster(int side, std::uint32_t seed = 1, double sigma = 1.5);

// A 64-bit hash of (x, y, seed): splitmix64's finaliser, the same on every platform.
std::uint64_t pixelHash(std::uint32_t x, std::uint32_t y, std::uint32_t seed);

// Orders any per-pixel keys into 256 levels with equal counts: the pixels sorted by (key, then
// tie), the one at rank r gets floor(256 r / n), n = keys.size(). So exactly ceil(k n / 256)
// pixels are below level k, for every k in 0..256: the fraction below k is k/256 within 1/n, and
// exactly k/256 when 256 divides n. keys and ties must have the same size (else
// std::invalid_argument).
std::vector<std::uint8_t> equalize(const std::vector<double>& keys, const std::vector<std::uint64_t>& ties);

// The pattern of a kind for a width x height image, equalized as above. Tiled kinds (Bayer 16x16,
// blue noise tileSide x tileSide) keep their tile's values exactly where the tiles cover the image
// whole times; elsewhere equalizing moves some pixels to a neighbouring level. Wipes: linear left
// to right, radial from the centre outwards, clock clockwise from twelve o'clock. Throws
// std::invalid_argument for a size below 1x1.
std::vector<std::uint8_t> makePattern(PatternKind, int width, int height, std::uint32_t seed = 1,
                                      int blueNoiseTileSide = 64);

// How many pixels of a pattern are below level k (0..256): those that show the second scene.
std::uint64_t countBelow(const std::vector<std::uint8_t>& pattern, int k);

// Clumpiness: the variance, over every window x window square wholly inside the image, of the
// fraction of its pixels below level k. 0 for a perfectly even spread; for white noise at
// coverage c it is about c(1 - c) / window^2; a wipe's is near c(1 - c). Throws
// std::invalid_argument if the window does not fit or the pattern's size is not width * height.
double coverageVariance(const std::vector<std::uint8_t>& pattern, int width, int height, int k,
                        int window = 8);

}  // namespace stencil
