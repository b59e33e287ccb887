#version 330 core
// Writes one bit plane of the threshold pattern into the stencil. The draw runs with the stencil
// test failing everywhere (NEVER), REPLACE on fail and the write mask on one bit: every fragment
// that reaches the test sets that bit. So the fragments of pixels whose pattern value has the bit
// clear are discarded here, before the test.
uniform sampler2D pattern;  // R8: the pattern value / 255, texel (x, y) for window pixel (x, y)
uniform int bit;            // 0..7

void main() {
  int value = int(texelFetch(pattern, ivec2(gl_FragCoord.xy), 0).r * 255.0 + 0.5);
  if (((value >> bit) & 1) == 0) discard;
}
