// Angular falloff of a spot light, one definition for the renderer (mirrored in
// shaders/lights.glsl) and the path tracer. With cosθ the cosine between the spot's
// direction and the direction to the lit point:
//   t = clamp((cosθ − cos(outer)) / (cos(inner) − cos(outer)), 0, 1),  factor = t²
// so the intensity is I·factor W/sr: full inside the inner cone, zero outside the outer one.
#pragma once

#include <algorithm>
#include <cmath>

#include "scene/scene.h"

namespace bounce {

inline float spotFalloff(const Light& light, float cosTheta) {
  const float cosOuter = std::cos(light.outerConeAngle);
  const float cosInner = std::cos(light.innerConeAngle);
  const float t =
      std::clamp((cosTheta - cosOuter) / std::max(cosInner - cosOuter, 1e-4f), 0.0f, 1.0f);
  return t * t;
}

}  // namespace bounce
