#version 330 core
// shaders/common/lit.frag with extra work per fragment (the `work` option): a stand-in for the
// costly shading of a real scene, so that what a method saves by shading fewer fragments shows in
// its time. With work = 0 the colour is lit.frag's.
in vec3 worldNormal;

uniform vec3 colour;
uniform vec3 toLight;  // unit vector towards the light
uniform float ambient;
uniform int work;  // iterations of busy arithmetic per fragment

out vec4 fragColour;

void main() {
  float diffuse = max(dot(normalize(worldNormal), toLight), 0.0);
  fragColour = vec4(colour * (ambient + (1.0 - ambient) * diffuse), 1.0);
  float busy = fract(gl_FragCoord.x * 0.001);  // in [0, 1), as every iteration leaves it
  for (int i = 0; i < work; ++i) busy = fract(sin(busy) * 43758.5453 + float(i));
  if (busy > 2.0) fragColour = vec4(1.0, 0.0, 1.0, 1.0);  // never: fract stays below 1
}
