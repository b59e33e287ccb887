#version 330 core
// Polished marble, lit like light.frag, with an alpha: drawn over a reflection it lets the
// reflection show through as a polished stone surface does. Veins from a sum of sines, so
// every rasteriser computes the same pattern.
in vec3 worldPosition;
in vec3 worldNormal;

uniform vec3 colour;  // the stone's base colour
uniform vec3 ambient;
uniform vec4 light;  // w = 1 a point, w = 0 a direction towards the light
uniform vec3 lightColour;
uniform vec3 eye;
uniform float shininess;
uniform float alpha;  // how much of the stone covers the reflection

out vec4 fragColour;

void main() {
  vec3 p = worldPosition * 2.5;
  float turbulence = 0.5 * sin(p.x * 1.7 + p.y * 2.3) + 0.25 * sin(p.y * 4.1 - p.z * 3.7) +
                     0.125 * sin(p.z * 8.3 + p.x * 7.9);
  float vein = pow(abs(sin(p.x + p.y * 0.6 + p.z * 0.8 + 2.5 * turbulence)), 0.35);
  vec3 albedo = mix(colour * 0.45, colour, vein);

  vec3 n = normalize(worldNormal);
  vec3 toLight = light.xyz - light.w * worldPosition;
  float distance = length(toLight);
  toLight /= distance;
  float falloff = light.w == 0.0 ? 1.0 : 1.0 / (1.0 + 0.04 * distance * distance);
  float diffuse = max(dot(n, toLight), 0.0);
  vec3 halfway = normalize(toLight + normalize(eye - worldPosition));
  float highlight = diffuse > 0.0 ? pow(max(dot(n, halfway), 0.0), shininess) : 0.0;
  vec3 lit = lightColour * falloff * (albedo * diffuse + vec3(0.6 * highlight));
  fragColour = vec4(albedo * ambient + lit, alpha);
}
