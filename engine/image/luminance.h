// Luminance of a linear-RGB value (sRGB / Rec. 709 primaries, D65 white): the Y row of the
// RGB → XYZ matrix, Y = 0.2126 R + 0.7152 G + 0.0722 B, in the unit of its input (a radiance
// gives a luminance-weighted radiance, an irradiance a luminance-weighted irradiance, a flux a
// luminance-weighted flux). The one place these weights are written in C++; the GLSL copy is
// shaders/lightmap.glsl's luminance(), which must stay equal to it.
#pragma once

#include <glm/glm.hpp>

namespace bounce {

inline float luminance(glm::vec3 rgb) {
  return 0.2126f * rgb.r + 0.7152f * rgb.g + 0.0722f * rgb.b;
}
inline double luminance(glm::dvec3 rgb) {
  return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b;
}

}  // namespace bounce
