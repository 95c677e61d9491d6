#version 330 core
// One forward pass: outgoing radiance (W/(sr·m²)) of a Lambertian surface under direct light,
//   L_o = ρ/π · (E_punctual + E_area) + L_e,
// into a linear float target. ρ = albedo × base-colour texel (linear), L_e the surface's own
// emission (front face; both when double-sided). Unshadowed.
#include "lights.glsl"
#include "area_light.glsl"

in vec3 vWorldPosition;
in vec3 vNormal;
in vec2 vUv;

uniform vec3 uAlbedo;              // ρ, linear RGB
uniform vec3 uEmission;            // W/(sr·m²)
uniform bool uHasAlbedoTexture;
uniform sampler2D uAlbedoTexture;  // linear RGB texels

out vec4 fragRadiance;

void main() {
  // Single-sided back faces are culled, so a back face here is double-sided: shade its side.
  vec3 n = normalize(vNormal);
  if (!gl_FrontFacing) n = -n;
  vec3 albedo = uAlbedo;
  if (uHasAlbedoTexture) albedo *= texture(uAlbedoTexture, vUv).rgb;
  vec3 irradiance = punctualIrradiance(vWorldPosition, n) + areaIrradiance(vWorldPosition, n);
  fragRadiance = vec4(albedo / PI * irradiance + uEmission, 1.0);
}
