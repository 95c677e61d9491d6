#version 330 core
// The viewer's display pass: linear radiance from the HDR target to display sRGB.
#include "tonemap.glsl"

in vec2 vUv;
uniform sampler2D uRadiance;  // W/(sr·m²)
uniform float uExposureEV;

out vec4 fragColor;

void main() {
  fragColor = vec4(toneMap(texture(uRadiance, vUv).rgb, uExposureEV), 1.0);
}
