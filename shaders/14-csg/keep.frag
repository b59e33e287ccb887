#version 330 core
// Lesson 14's automatic method, layered Goldfeather: a layer's trimmed surface (the work buffer's
// depth and primitive) kept where it is nearer than the layers before it (the depth test), so
// that the product's targets are merged into the frame once, not once a layer.
uniform sampler2D productDepth;       // the layer's trimmed surface, window depth per pixel
uniform usampler2D productPrimitive;  // and the primitive whose fragment wrote that depth

layout(location = 1) out uint nearestPrimitive;  // the buffers are made alike (Csg::workBuffer)

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  gl_FragDepth = texelFetch(productDepth, pixel, 0).r;
  nearestPrimitive = texelFetch(productPrimitive, pixel, 0).r;
}
