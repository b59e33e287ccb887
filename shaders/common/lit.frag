#version 330 core
// One directional light plus ambient: enough shading to read shapes, nothing more.
in vec3 worldNormal;

uniform vec3 colour;
uniform vec3 toLight;  // unit vector towards the light
uniform float ambient;

out vec4 fragColour;

void main() {
  float diffuse = max(dot(normalize(worldNormal), toLight), 0.0);
  fragColour = vec4(colour * (ambient + (1.0 - ambient) * diffuse), 1.0);
}
