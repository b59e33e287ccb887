#version 330 core
// Every point light of the round at once, added where they all agree the pixel is lit (outside
// the penumbra wedges): light.frag's term per light, summed in the lights' order, with alpha
// counting the lights as one addition each would.
in vec3 worldPosition;
in vec3 worldNormal;

uniform vec3 colour;       // albedo
uniform sampler2D lights;  // N x 1, RGBA32F: the point lights (w = 1)
uniform int count;         // N
uniform vec3 lightColour;  // each light's share
uniform vec3 eye;
uniform float shininess;

out vec4 fragColour;

void main() {
  vec3 n = normalize(worldNormal);
  vec3 sum = vec3(0.0);
  for (int i = 0; i < count; ++i) {
    vec4 light = texelFetch(lights, ivec2(i, 0), 0);
    vec3 toLight = light.xyz - light.w * worldPosition;
    float distance = length(toLight);
    toLight /= distance;
    float falloff = 1.0 / (1.0 + 0.04 * distance * distance);
    float diffuse = max(dot(n, toLight), 0.0);
    vec3 halfway = normalize(toLight + normalize(eye - worldPosition));
    float highlight = diffuse > 0.0 ? pow(max(dot(n, halfway), 0.0), shininess) : 0.0;
    sum += lightColour * falloff * (colour * diffuse + vec3(0.6 * highlight));
  }
  fragColour = vec4(sum, float(count));
}
