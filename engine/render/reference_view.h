// How the viewer shows its frame beside a reference image (a bounce-trace EXR of the same camera),
// GL-free; shaders/reference_compare.frag composes the same picture and must stay equal to this.
// The picture is made in radiance (W/(sr·m²)), before tone mapping, so both sides go through the
// same exposure and tone mapper.
//
//   split       pixels left of the middle column (x < width/2) the frame's, the others the
//               reference's;
//   difference  the luminance relative difference d = (lum L − lum L_ref) / lum L_ref per pixel
//               as a false colour: red where the frame is brighter, blue where it is darker, at
//               full strength from |d| = kDifferenceFullScale, black where they agree (both
//               below kDifferenceFloor counts as agreeing). The colours are the view's output
//               radiance, as the chart view's are: a picture, not light.
// A reference of another size is sampled at the nearest texel of the same relative position.
#pragma once

#include <optional>
#include <string_view>

#include <glm/vec3.hpp>

namespace bounce {

enum class ReferenceView { Off, Split, Difference };

inline constexpr float kDifferenceFullScale = 0.5f;  // |d| where the colour saturates
inline constexpr float kDifferenceFloor = 1e-6f;     // luminance, W/(sr·m²)

std::string_view referenceViewName(ReferenceView view);  // "off", "split", "difference"
std::optional<ReferenceView> parseReferenceView(std::string_view name);

// The difference view's colour for a frame pixel against the reference's.
glm::vec3 relativeDifferenceColour(glm::vec3 frame, glm::vec3 reference);

}  // namespace bounce
