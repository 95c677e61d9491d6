// Display mapping, the same on the CPU (PNG files) and in shaders/tonemap.glsl (viewer):
//   1. exposure: x = L · 2^EV  (L linear radiance, W/(sr·m²); EV = 0 maps L = 1 to x = 1);
//   2. the filmic curve x(2.51x+0.03) / (x(2.43x+0.59)+0.14), clamped to [0,1] (an
//      analytic fit to the ACES reference rendering transform, per channel);
//   3. the sRGB transfer function (IEC 61966-2-1).
#pragma once

#include <glm/glm.hpp>

namespace bounce {

float filmicCurve(float x);
float srgbEncode(float linear01);
// Linear radiance to display sRGB in [0,1].
glm::vec3 toneMap(glm::vec3 radiance, float exposureEV);

}  // namespace bounce
