#version 330 core
// The viewer's display pass: linear radiance from the HDR target to display sRGB; in the cost
// view (uCostChannel ≥ 0) one count of the frame (R lights, G VPLs, B shadow-map taps) in false
// colour with its legend bar instead (cost_colour.glsl).
#include "tonemap.glsl"
#include "cost_colour.glsl"

in vec2 vUv;
uniform sampler2D uRadiance;  // W/(sr·m²), or counts in the cost view
uniform float uExposureEV;
uniform int uCostChannel;     // −1: radiance; 0, 1, 2: the count shown
uniform float uCostMax;       // the scale's end
uniform int uCostLegendRows;  // the bar's height, pixels

out vec4 fragColor;

void main() {
  vec3 texel = texture(uRadiance, vUv).rgb;
  if (uCostChannel < 0) {
    fragColor = vec4(toneMap(texel, uExposureEV), 1.0);
    return;
  }
  vec3 colour;
  ivec2 size = textureSize(uRadiance, 0);
  ivec2 p = ivec2(vUv * vec2(size));
  if (!costLegend(p, size, uCostLegendRows, uCostMax, colour))
    colour = costColour(texel[uCostChannel], uCostMax);
  fragColor = vec4(colour, 1.0);
}
