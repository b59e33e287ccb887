#version 330 core
#extension GL_ARB_shader_stencil_export : enable
// Lesson 14's merge, its first pass: one full-screen quad that writes the product's surface (the
// work buffer's depth) into the frame's depth where it is nearer than what the frame holds, and
// the primitive whose fragment made it (its index modulo 255, + 1) into the frame's stencil. The
// targets are then drawn lit where the frame holds exactly their depth and their primitive: that
// pass writes nothing but colour and has no depth to write, so llvmpipe tests depth and stencil
// before shading, where a merge that compared in the shader ran the lighting on every fragment.
uniform sampler2D productDepth;       // the product's trimmed surface, window depth per pixel
uniform usampler2D productPrimitive;  // the primitive whose fragment wrote it (index + 1; 0 none)

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uint primitive = texelFetch(productPrimitive, pixel, 0).r;
  if (primitive == 0u) discard;  // no target's fragment wrote this depth (the entry's near plane)
  gl_FragDepth = texelFetch(productDepth, pixel, 0).r;
#ifdef GL_ARB_shader_stencil_export  // else the lit pass writes the tag (Csg::mergeIntoFrame)
  gl_FragStencilRefARB = int((primitive - 1u) % 255u + 1u);
#endif
}
