#include "atlas/texel_density.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace bounce {
namespace {

std::string metres(double m) {
  std::ostringstream s;
  s.precision(3);
  if (m < 1.0)
    s << m * 100.0 << " cm";
  else
    s << m << " m";
  return s.str();
}

}  // namespace

TexelDensity chooseTexelDensity(double weightedArea, const TexelDensityRequest& request) {
  if (!(request.texelSize >= 0.0f) || !std::isfinite(request.texelSize))
    throw std::invalid_argument("the texel size must be a positive number of metres (or 0)");
  if (request.texelBudget < 0) throw std::invalid_argument("the texel budget must be ≥ 1 texel");
  if (request.maxTexels < 1) throw std::invalid_argument("the texel cap must be ≥ 1 texel");
  if (!(weightedArea > 0.0) || !std::isfinite(weightedArea))
    throw std::invalid_argument("the static surface area must be positive and finite");

  TexelDensity d;
  double t = 0.0;
  if (request.texelSize > 0.0f) {
    t = request.texelSize;
    d.rule = "as asked";
  } else if (request.texelBudget > 0) {
    t = std::sqrt(weightedArea / request.texelBudget);
    d.rule = "from a budget of " + std::to_string(request.texelBudget) + " texels";
  } else {
    const double small = std::sqrt(weightedArea / kSmallSceneTexels);
    t = std::min(static_cast<double>(kRoomTexelSize), small);
    d.rule = t < kRoomTexelSize ? "a small scene's " + std::to_string(kSmallSceneTexels) + " texels"
                                : metres(kRoomTexelSize) + ", the room default";
  }
  const double texels = weightedArea / (t * t);
  if (texels > static_cast<double>(request.maxTexels)) {
    const double capped = std::sqrt(weightedArea / static_cast<double>(request.maxTexels));
    std::ostringstream note;
    note << "the static surface (" << weightedArea << " m² weighted by lightmapScale²) would take "
         << static_cast<int64_t>(std::ceil(texels)) << " texels at " << metres(t)
         << ", over the cap of " << request.maxTexels << ": the texels are " << metres(capped)
         << " instead (raise --max-texels, or lower extras.bounce.lightmapScale where less detail "
            "will do)";
    d.note = note.str();
    d.rule = "capped at " + std::to_string(request.maxTexels) + " texels";
    t = capped;
  }
  d.texelSize = static_cast<float>(t);
  return d;
}

}  // namespace bounce
