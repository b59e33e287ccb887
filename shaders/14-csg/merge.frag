#version 330 core
#extension GL_ARB_shader_image_load_store : enable
// Lesson 14's surfaces, lit like common/light.frag with the side the eye sees lit. Two uses:
// selecting (merging 0): into the work buffer, every fragment kept, its primitive written beside
// its depth, so the work buffer records which primitive's fragment the trimming keeps at each
// pixel; merging (1): a target drawn again into the frame, kept only where it is the product's
// surface: the work buffer holds its primitive at exactly its depth (the same triangle drawn
// again lands on the same depth: gl_Position is invariant). The merge's first pass has put that
// depth and primitive into the frame (14-csg/resolve.frag), and the depth and stencil tests
// (EQUAL) pass only there: the comparisons here settle what the tests cannot (two primitives
// whose tags, modulo 255, are the same; two faces in one step of a 24-bit depth).
// The tests run before the shader: a merge writes only colour, and the lighting then runs only on
// the fragments that pass (a shader that may discard otherwise waits for the shader to test).
// Without stencil export the merge writes each target's tag itself, so the shader must decide
// first (and without early_fragment_tests, as in WebGL 2, the tests simply wait).
#if defined(GL_ARB_shader_image_load_store) && defined(GL_ARB_shader_stencil_export)
layout(early_fragment_tests) in;
#endif
in vec3 worldPosition;
in vec3 worldNormal;
flat in int fragmentPrimitive;  // this primitive's index + 1 (merge.vert)

uniform bool merging;
uniform sampler2D productDepth;       // the product's trimmed surface, window depth per pixel
uniform usampler2D productPrimitive;  // and the primitive whose fragment wrote that depth
uniform vec3 colour;
uniform vec3 ambient;
uniform vec4 light;
uniform vec3 lightColour;
uniform vec3 eye;
uniform float shininess;

layout(location = 0) out vec4 fragColour;
layout(location = 1) out uint fragPrimitive;

void main() {
  if (merging) {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (texelFetch(productPrimitive, pixel, 0).r != uint(fragmentPrimitive) ||
        texelFetch(productDepth, pixel, 0).r != gl_FragCoord.z)
      discard;
  }
  fragPrimitive = uint(fragmentPrimitive);
  vec3 n = normalize(worldNormal);
  if (!gl_FrontFacing) n = -n;  // a subtracted primitive's back face is seen from inside
  vec3 toLight = light.xyz - light.w * worldPosition;
  float distance = length(toLight);
  toLight /= distance;
  float falloff = light.w == 0.0 ? 1.0 : 1.0 / (1.0 + 0.04 * distance * distance);
  float diffuse = max(dot(n, toLight), 0.0);
  vec3 halfway = normalize(toLight + normalize(eye - worldPosition));
  float highlight = diffuse > 0.0 ? pow(max(dot(n, halfway), 0.0), shininess) : 0.0;
  vec3 lit = lightColour * falloff * (colour * diffuse + vec3(0.6 * highlight));
  fragColour = vec4(colour * ambient + lit, 1.0);
}
