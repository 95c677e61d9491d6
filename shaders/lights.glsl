// Punctual lights (point, spot, directional): the irradiance E (W/m²) they give a surface at
// world point p with unit shading normal n and geometric normal ng, times the light's
// visibility V ∈ [0,1] from its shadow map (lightVisibility, shaders/shadows.glsl):
//   point:       E = I · cosθ / r²            (I in W/sr, r in m)
//   spot:        E = I · spotFalloff · cosθ / r²
//   directional: E = E⊥ · cosθ                (E⊥ in W/m² on a surface facing the light)
// with cosθ = max(n·l, 0), l the unit direction towards the light.

// Visibility of light i from p (1 = lit); defined in shadows.glsl.
float lightVisibility(int light, vec3 p, vec3 ng);

const float PI = 3.14159265358979;
const int MAX_PUNCTUAL_LIGHTS = 32;
const int LIGHT_POINT = 0;
const int LIGHT_SPOT = 1;
const int LIGHT_DIRECTIONAL = 2;

uniform int uLightCount;
uniform int uLightType[MAX_PUNCTUAL_LIGHTS];
uniform vec3 uLightPosition[MAX_PUNCTUAL_LIGHTS];   // metres (point, spot)
uniform vec3 uLightDirection[MAX_PUNCTUAL_LIGHTS];  // unit, the way light travels
uniform vec3 uLightPower[MAX_PUNCTUAL_LIGHTS];      // intensity W/sr, or irradiance W/m²
uniform vec2 uLightCosCone[MAX_PUNCTUAL_LIGHTS];    // spot: cos(inner), cos(outer)

// Mirrors bounce::spotFalloff (engine/scene/light_falloff.h) exactly:
//   t = clamp((cosθ − cos outer) / max(cos inner − cos outer, 1e-4), 0, 1), factor t².
float spotFalloff(vec2 cosCone, float cosTheta) {
  float t = clamp((cosTheta - cosCone.y) / max(cosCone.x - cosCone.y, 1e-4), 0.0, 1.0);
  return t * t;
}

vec3 punctualIrradiance(vec3 p, vec3 n, vec3 ng) {
  vec3 irradiance = vec3(0.0);
  for (int i = 0; i < uLightCount; ++i) {
    if (uLightType[i] == LIGHT_DIRECTIONAL) {
      float cosTheta = max(dot(n, -uLightDirection[i]), 0.0);
      if (cosTheta > 0.0) irradiance += uLightPower[i] * cosTheta * lightVisibility(i, p, ng);
      continue;
    }
    vec3 toLight = uLightPosition[i] - p;
    float r2 = dot(toLight, toLight);
    vec3 l = toLight * inversesqrt(r2);
    vec3 intensity = uLightPower[i];
    if (uLightType[i] == LIGHT_SPOT) intensity *= spotFalloff(uLightCosCone[i], dot(-l, uLightDirection[i]));
    float cosTheta = max(dot(n, l), 0.0);
    if (cosTheta > 0.0 && intensity != vec3(0.0))
      irradiance += intensity * cosTheta / r2 * lightVisibility(i, p, ng);
  }
  return irradiance;
}
