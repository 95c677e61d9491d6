// Punctual lights (point, spot, directional): the irradiance E (W/m²) they give a surface at
// world point p with unit shading normal n and geometric normal ng, times the light's
// visibility V ∈ [0,1] from its shadow map (lightVisibility, shaders/shadows.glsl):
//   point:       E = I · cosθ / r²            (I in W/sr, r in m)
//   spot:        E = I · spotFalloff · cosθ / r²
//   directional: E = E⊥ · cosθ                (E⊥ in W/m² on a surface facing the light)
// with cosθ = max(n·l, 0), l the unit direction towards the light. Summed over the lights of
// the fragment's cluster (light_grid.glsl), each read by its own index.
//
// A light that does not move, on a static surface of a bake with visibility, also has its
// visible fraction baked per lightmap texel (baked_visibility.glsl): ray-traced against the
// static scene, so it holds where shadow maps fail (contact under thin walls, acne, peter-
// panning). The shadow map still draws the dynamic instances, so V = min(V_map, V_baked): each
// is ≈ 0 where its occluders hide the light, and the baked one corrects the map's leaks.

#include "cost.glsl"
#include "light_table.glsl"
#include "light_grid.glsl"

// Visibility of `light` from p (1 = lit); defined in shadows.glsl.
float lightVisibility(PunctualLight light, vec3 p, vec3 ng);

// Mirrors bounce::spotFalloff (engine/scene/light_falloff.h) exactly:
//   t = clamp((cosθ − cos outer) / max(cos inner − cos outer, 1e-4), 0, 1), factor t².
float spotFalloff(vec2 cosCone, float cosTheta) {
  float t = clamp((cosTheta - cosCone.y) / max(cosCone.x - cosCone.y, 1e-4), 0.0, 1.0);
  return t * t;
}

// V of `light` at p: its shadow map's, and on a baked static surface the smaller of that and
// its baked visible fraction where the texels name it. A light with a map ignores the texels'
// shared "every other light" slot (a mix of other lights' V, no bound on its own); a light
// without one takes it, as the area lights do.
//
// Where the texels give the light V = 0, min(V_map, V) is 0 whatever the map says: no tap.
// (Skipping the map where they give V = 1 as well was tried: on the sunlit room the cascades
// still darken some of those pixels rightly, 1.21% -> 1.32% off the tracer.)
float punctualVisibility(PunctualLight light, vec3 p, vec3 ng, BakedVisibilityTexels baked) {
  float v = 1.0;
  if (uHasBakedVisibility && light.bakedIndex >= 0)
    v = bakedVisibility(baked, light.bakedIndex, light.shadowSlot < 0);
  if (v > 0.0) v = min(v, lightVisibility(light, p, ng));
  return v;
}

// `fromTexels`: the precomputed lights' direct light is read from the texels or corners
// (static_direct.glsl), V·E with V their baked visibility (shared slot); such a light is
// evaluated here only while it has a shadow map (a dynamic caster in its reach), as the
// correction E·(V − V_baked). The lists put the precomputed lights without a map first
// (PunctualLights::listOrder), so walked from the end the first one ends the walk: the loop runs
// over the other lights only (a shader runs a loop until every lane has left it).
vec3 punctualIrradiance(LightList lights, vec3 p, vec3 n, vec3 ng, BakedVisibilityTexels baked,
                        bool fromTexels) {
  vec3 irradiance = vec3(0.0);
  int count = lights.all ? uPunctualCount : lights.punctualCount;
  for (int k = count - 1; k >= 0; --k) {
    PunctualLight light = punctualLight(punctualLightIndex(lights, k));
    bool inTexels = fromTexels && light.precomputed && uHasBakedVisibility;
    if (inTexels && light.shadowSlot < 0) {
      if (lights.all) continue;  // every light in index order: no ordering to stop on
      break;
    }
    gCostLights += 1;
    if (light.power == vec3(0.0)) continue;
    vec3 e;
    if (light.type == LIGHT_DIRECTIONAL) {
      e = light.power * max(dot(n, -light.direction), 0.0);
    } else {
      vec3 toLight = light.position - p;
      float r2 = dot(toLight, toLight);
      vec3 l = toLight * inversesqrt(r2);
      vec3 intensity = light.power;
      if (light.type == LIGHT_SPOT)
        intensity *= spotFalloff(light.cosCone, dot(-l, light.direction));
      e = intensity * max(dot(n, l), 0.0) / r2;
    }
    if (e == vec3(0.0)) continue;
    float v = punctualVisibility(light, p, ng, baked);
    if (inTexels) v -= bakedVisibility(baked, light.bakedIndex, true);
    irradiance += e * v;
  }
  return irradiance;
}
