#version 330 core
// shaders/common/lit.frag that first shades, then discards the fragments its scene does not show:
// the dithered cross-fade engines use (a threshold pattern read in the fragment shader), here as
// the measured alternative to the stencil test. Every fragment of both scenes is shaded.
in vec3 worldNormal;

uniform vec3 colour;
uniform vec3 toLight;  // unit vector towards the light
uniform float ambient;
uniform sampler2D pattern;  // R8: the pattern value / 255, texel = window pixel
uniform int state;          // k, 0..256
uniform int sceneB;         // 1: keep where the pattern value is below k; 0: where it is not
uniform int work;           // iterations of busy arithmetic per fragment (lit_work.frag)

out vec4 fragColour;

void main() {
  float diffuse = max(dot(normalize(worldNormal), toLight), 0.0);
  fragColour = vec4(colour * (ambient + (1.0 - ambient) * diffuse), 1.0);
  float busy = fract(gl_FragCoord.x * 0.001);  // in [0, 1), as every iteration leaves it
  for (int i = 0; i < work; ++i) busy = fract(sin(busy) * 43758.5453 + float(i));
  if (busy > 2.0) fragColour = vec4(1.0, 0.0, 1.0, 1.0);  // never: fract stays below 1
  int value = int(texelFetch(pattern, ivec2(gl_FragCoord.xy), 0).r * 255.0 + 0.5);
  if ((value < state) != (sceneB == 1)) discard;
}
