// The bake's per-texel estimated error (error.exr, bake_folder.h) as a picture: a false colour
// per texel against the bake's target error, for the renderer's error view. GL-free.
//
//   relative error e / target:  0 → blue (0, 0, 1),  1 → green (0, 1, 0),  ≥ 2 → red (1, 0, 0),
//   linear between; a texel without an estimate (kNoErrorEstimate) → dark grey (0.05).
// The colours are the view's output radiance in W/(sr·m²), as the chart view's are: a picture,
// not light.
#pragma once

#include <string>

#include <glm/vec3.hpp>

#include "image/image.h"

namespace bounce {

inline constexpr float kDefaultErrorTarget = 0.1f;  // when bake.json does not give one

// bake.json's "estimatedError"."target" (the relative error the bake aimed at), or
// kDefaultErrorTarget where it is missing or not a positive number.
float bakeErrorTarget(const std::string& manifestJson);

glm::vec3 errorFalseColour(float relativeError, float target);

// errorFalseColour of every texel of `relativeError` (error.exr).
Image errorFalseColourImage(const Image& relativeError, float target);

}  // namespace bounce
