#include "render/reference_view.h"

#include <algorithm>
#include <array>

#include "image/luminance.h"

namespace bounce {

std::string_view referenceViewName(ReferenceView view) {
  switch (view) {
    case ReferenceView::Off:
      return "off";
    case ReferenceView::Split:
      return "split";
    case ReferenceView::Difference:
      return "difference";
  }
  return "off";
}

std::optional<ReferenceView> parseReferenceView(std::string_view name) {
  for (const ReferenceView view :
       std::array{ReferenceView::Off, ReferenceView::Split, ReferenceView::Difference})
    if (referenceViewName(view) == name) return view;
  return std::nullopt;
}

glm::vec3 relativeDifferenceColour(glm::vec3 frame, glm::vec3 reference) {
  const float l = luminance(frame), lRef = luminance(reference);
  if (l < kDifferenceFloor && lRef < kDifferenceFloor) return glm::vec3(0.0f);
  const float d = (l - lRef) / std::max(lRef, kDifferenceFloor);
  const float strength = std::min(std::abs(d) / kDifferenceFullScale, 1.0f);
  return d > 0.0f ? glm::vec3(strength, 0.0f, 0.0f) : glm::vec3(0.0f, 0.0f, strength);
}

}  // namespace bounce
