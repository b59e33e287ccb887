#version 330 core
// Draw both and mix: both scenes rendered whole into textures, then one full-screen pass picks,
// per pixel, the scene the threshold pattern says: B where the pattern value is below the state k.
uniform sampler2D sceneA, sceneB, pattern;  // all the framebuffer's size, texel = window pixel
uniform int state;                          // k, 0..256

out vec4 fragColour;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  int value = int(texelFetch(pattern, p, 0).r * 255.0 + 0.5);
  fragColour = value < state ? texelFetch(sceneB, p, 0) : texelFetch(sceneA, p, 0);
}
