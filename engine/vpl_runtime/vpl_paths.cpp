#include "vpl_runtime/vpl_paths.h"

#include <algorithm>

namespace bounce {

uint64_t vplPathCount(std::span<const Vpl> vpls, uint64_t bakePaths) {
  if (bakePaths > 0) return bakePaths;
  uint64_t paths = 0;
  for (const Vpl& vpl : vpls) paths = std::max(paths, static_cast<uint64_t>(vpl.path) + 1);
  return paths;
}

std::vector<Vpl> firstPathsVpls(std::span<const Vpl> vpls, uint64_t paths, uint64_t totalPaths) {
  if (paths >= totalPaths) return {vpls.begin(), vpls.end()};
  std::vector<Vpl> kept;
  if (paths == 0) return kept;
  const float scale =
      static_cast<float>(static_cast<double>(totalPaths) / static_cast<double>(paths));
  for (const Vpl& vpl : vpls)
    if (vpl.path < paths) {
      kept.push_back(vpl);
      kept.back().flux *= scale;
    }
  return kept;
}

}  // namespace bounce
