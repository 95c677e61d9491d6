// Visibility of each punctual light, from its shadow map: the one place lights.glsl asks.
// uLightShadow[i] is light i's slot among its kind's maps, or −1 when it has none (unshadowed).
// Each kind's lookup is its own file.
#include "shadow_common.glsl"
#include "shadow_spot.glsl"
#include "shadow_point.glsl"

uniform int uLightShadow[MAX_PUNCTUAL_LIGHTS];

float lightVisibility(int light, vec3 p, vec3 ng) {
  int slot = uLightShadow[light];
  if (slot < 0) return 1.0;
  if (uLightType[light] == LIGHT_SPOT) return spotShadow(slot, p, ng, uLightPosition[light]);
  if (uLightType[light] == LIGHT_POINT) return pointShadow(slot, p, ng, uLightPosition[light]);
  return 1.0;
}
