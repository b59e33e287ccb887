#version 330 core
// Ambient plus one light: diffuse and a Blinn-Phong highlight, fading with distance.
// Drawing with lightColour = 0 gives the ambient term alone; with ambient = 0, the light's
// contribution alone, to be added onto what is there. A point light with a radius (its
// bounds, docs/scenes.md) reaches exactly zero there: outside them it adds nothing, so nothing
// outside needs its shadow (lesson 16's scissor rectangle and caster culling).
in vec3 worldPosition;
in vec3 worldNormal;

uniform vec3 colour;       // albedo
uniform vec3 ambient;      // ambient light
uniform vec4 light;        // w = 1 a point, w = 0 a direction towards the light
uniform vec3 lightColour;  // 0 turns the light off
uniform vec3 eye;
uniform float shininess;
uniform float radius = 1e30;  // a point light's bounds; the default leaves the fall-off alone
uniform int twoSided = 0;     // 1: a face seen from its back is lit on that side (rooms, lessons 15-16)

out vec4 fragColour;

void main() {
  vec3 n = normalize(worldNormal);
  if (twoSided != 0 && !gl_FrontFacing) n = -n;  // the side the eye sees
  vec3 toLight = light.xyz - light.w * worldPosition;
  float distance = length(toLight);
  toLight /= distance;
  float window = light.w == 0.0 ? 1.0 : pow(max(1.0 - pow(distance / radius, 2.0), 0.0), 2.0);
  float falloff = light.w == 0.0 ? 1.0 : window / (1.0 + 0.04 * distance * distance);
  float diffuse = max(dot(n, toLight), 0.0);
  vec3 halfway = normalize(toLight + normalize(eye - worldPosition));
  float highlight = diffuse > 0.0 ? pow(max(dot(n, halfway), 0.0), shininess) : 0.0;
  vec3 lit = lightColour * falloff * (colour * diffuse + vec3(0.6 * highlight));
  fragColour = vec4(colour * ambient + lit, 1.0);
}
