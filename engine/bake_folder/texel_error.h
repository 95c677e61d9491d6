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

#include "bake_folder/bake_manifest.h"
#include "image/image.h"

namespace bounce {

inline constexpr float kDefaultErrorTarget = 0.1f;  // when bake.json does not give one

// bake.json's "estimatedError"."target" (the relative error the bake aimed at), or
// kDefaultErrorTarget where it is not a positive number (0 in a hand-made manifest).
float bakeErrorTarget(const BakeManifest& manifest);

glm::vec3 errorFalseColour(float relativeError, float target);

// errorFalseColour of every texel of `relativeError` (error.exr).
Image errorFalseColourImage(const Image& relativeError, float target);

// Texel validity, per texel: green (0, 0.8, 0) where it has samples of its own (an error
// estimate), orange (1, 0.5, 0) where a chart covers it but its value was filled from its
// neighbours (the leak guard dropped every sample point: inside geometry or across a wall),
// dark blue (0, 0, 0.35) in the padding between charts (dilated). `charts`: the chart image of
// the layout (bake_folder/lightmap_charts.h, black where no chart covers a texel).
inline constexpr glm::vec3 kValidTexel{0.0f, 0.8f, 0.0f};
inline constexpr glm::vec3 kFilledTexel{1.0f, 0.5f, 0.0f};
inline constexpr glm::vec3 kPaddingTexel{0.0f, 0.0f, 0.35f};
Image texelValidityImage(const Image& relativeError, const Image& charts);

}  // namespace bounce
