#include "bake_folder/lightmap_layout.h"

#include <algorithm>

namespace bounce {

const InstanceLightmapUv* LightmapLayout::find(uint32_t instance) const {
  const auto it = std::lower_bound(
      instances.begin(), instances.end(), instance,
      [](const InstanceLightmapUv& region, uint32_t i) { return region.instance < i; });
  if (it == instances.end() || it->instance != instance || it->cornerUv.empty()) return nullptr;
  return &*it;
}

}  // namespace bounce
