#version 330 core
// Goldfeather's merge: a primitive drawn again into the frame, kept only where its fragment is
// the product's surface (the depth the trimming left in productDepth at this pixel), then shaded
// like common/light.frag with the side the eye sees lit. The depth test against the frame keeps
// the nearest of every product's surfaces: their union.
in vec3 worldPosition;
in vec3 worldNormal;

uniform sampler2D productDepth;  // the product's trimmed surface, window depth per pixel
uniform float tolerance;         // the same fragment drawn twice lands within this
uniform vec3 colour;
uniform vec3 ambient;
uniform vec4 light;
uniform vec3 lightColour;
uniform vec3 eye;
uniform float shininess;

out vec4 fragColour;

void main() {
  if (abs(texelFetch(productDepth, ivec2(gl_FragCoord.xy), 0).r - gl_FragCoord.z) > tolerance) discard;
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
