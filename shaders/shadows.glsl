// Visibility of each punctual light, from its shadow map: the one place lights.glsl asks.
// light.shadowSlot is its slot among its kind's maps, or −1 when it has none (unshadowed).
// Each kind's lookup is its own file.
#include "shadow_common.glsl"
#include "shadow_spot.glsl"
#include "shadow_point.glsl"
#include "shadow_directional.glsl"
#include "shadow_area.glsl"

float lightVisibility(PunctualLight light, vec3 p, vec3 ng) {
  int slot = light.shadowSlot;
  if (slot < 0) return 1.0;
  if (light.type == LIGHT_SPOT) return spotShadow(slot, p, ng, light.position);
  if (light.type == LIGHT_POINT) return pointShadow(slot, p, ng, light.position);
  if (light.type == LIGHT_DIRECTIONAL) return directionalVisibility(p, ng, -light.direction);
  return 1.0;
}
