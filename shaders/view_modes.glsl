// The inspection views texel-density and cascades (engine/render/view_mode_colours.h says what
// they show; its colour formulas and these must stay equal). Needs lightmap.glsl (uHasLightmap,
// uLightmapSize) and shadow_directional.glsl (the cascades' view depths).

uniform float uTargetTexelsPerMetre;  // 1 / the bake's texel size (m)

// CASCADE_COLOURS, TEXEL_CHECKER_DARK and NO_LIGHTMAP_GREY come from view_mode_colours.h
// (engine/render/shader_constants.h).

// Lightmap texels per metre on the triangle: the square root of the atlas area (texels²) over
// the world area (m²) of the same screen footprint. Both the atlas UV and the position are affine
// over a triangle, so the ratio is the triangle's own, whatever the view. Call in uniform control
// flow (screen-space derivatives).
float texelsPerMetre(vec2 atlasUv, vec3 worldPosition) {
  vec2 tx = dFdx(atlasUv * uLightmapSize), ty = dFdy(atlasUv * uLightmapSize);
  float texelArea = abs(tx.x * ty.y - tx.y * ty.x);
  float worldArea = length(cross(dFdx(worldPosition), dFdy(worldPosition)));
  return worldArea > 0.0 ? sqrt(texelArea / worldArea) : 0.0;
}

vec3 texelDensityView(vec2 atlasUv, vec3 worldPosition) {
  float density = texelsPerMetre(atlasUv, worldPosition);
  if (!uHasLightmap || density <= 0.0) return vec3(NO_LIGHTMAP_GREY);
  float r = clamp(log2(density / uTargetTexelsPerMetre), -1.0, 1.0);
  vec3 colour = r <= 0.0 ? vec3(0.0, 1.0 + r, -r) : vec3(r, 1.0 - r, 0.0);
  ivec2 texel = ivec2(floor(atlasUv * uLightmapSize));
  return colour * (((texel.x + texel.y) & 1) == 0 ? 1.0 : TEXEL_CHECKER_DARK);
}

// The cascade colour at p (world metres), cross-faded in the blend bands as
// directionalVisibility is.
vec3 cascadeView(vec3 p) {
  if (uCascadeCount == 0) return vec3(NO_LIGHTMAP_GREY);
  float z = dot(p - uViewPosition, uViewForward);
  for (int i = 0; i < uCascadeCount; ++i) {
    vec4 depths = uCascadeDepths[i];
    bool last = i + 1 == uCascadeCount;
    if (z > depths.z && !last) continue;
    if (z > depths.y && !last) {
      float w = clamp((z - depths.y) / (depths.z - depths.y), 0.0, 1.0);
      return mix(CASCADE_COLOURS[i], CASCADE_COLOURS[i + 1], w);
    }
    return CASCADE_COLOURS[i];
  }
  return vec3(NO_LIGHTMAP_GREY);
}
