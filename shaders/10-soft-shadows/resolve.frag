#version 330 core
// The accumulated light onto the framework's picture (or into the running average). Alpha holds
// how many of the round's point lights reached the pixel: strictly between none and all of them
// is the penumbra, tinted on request.
uniform sampler2D picture;
uniform float lights;  // the point lights of a round
uniform int tint;      // 1: tint the penumbra

out vec4 fragColour;

void main() {
  vec4 c = texelFetch(picture, ivec2(gl_FragCoord.xy), 0);
  if (tint != 0 && c.a > 0.001 && c.a < lights - 0.001) c.rgb = mix(c.rgb, vec3(1.0, 0.15, 0.75), 0.5);
  fragColour = c;
}
