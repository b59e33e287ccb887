#version 330 core
// Lesson 14's flat passes: the depth and stencil passes (drawDepth, the colour mask off) and the
// quads that move pixels to the far plane (drawQuad). The primitive output (no primitive: 0) is
// there because WebGL 2 refuses a draw that leaves a draw buffer of the work buffer (its colour,
// its primitive) without an output.
uniform vec4 colour;

layout(location = 0) out vec4 fragColour;
layout(location = 1) out uint fragPrimitive;

void main() {
  fragColour = colour;
  fragPrimitive = 0u;
}
