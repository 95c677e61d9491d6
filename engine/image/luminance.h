// Luminance of a linear-RGB value (sRGB / Rec. 709 primaries, D65 white): the Y row of the
// RGB → XYZ matrix, Y = 0.2126 R + 0.7152 G + 0.0722 B, in the unit of its input (a radiance
// gives a luminance-weighted radiance, an irradiance a luminance-weighted irradiance, a flux a
// luminance-weighted flux). The one place these weights are written; the shaders get them as
// LUMINANCE_WEIGHTS (render/shader_constants.h).
#pragma once

#include <algorithm>

#include <glm/glm.hpp>

namespace bounce {

inline constexpr double kLuminanceR = 0.2126;
inline constexpr double kLuminanceG = 0.7152;
inline constexpr double kLuminanceB = 0.0722;

inline float luminance(glm::vec3 rgb) {
  return static_cast<float>(kLuminanceR) * rgb.r + static_cast<float>(kLuminanceG) * rgb.g +
         static_cast<float>(kLuminanceB) * rgb.b;
}
inline double luminance(glm::dvec3 rgb) {
  return kLuminanceR * rgb.r + kLuminanceG * rgb.g + kLuminanceB * rgb.b;
}

// The largest channel of a linear-RGB value, 0 when none is positive: the bound the renderer's
// light budgets rank lights by (a light bright in one channel only still counts).
inline float brightestChannel(glm::vec3 rgb) {
  return std::max({rgb.r, rgb.g, rgb.b, 0.0f});
}

}  // namespace bounce
