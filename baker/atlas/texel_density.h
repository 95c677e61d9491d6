// The lightmap's texel size: one rule, used by bounce-atlas and bounce-bake alike (through
// AtlasSettings), so the atlas a user previews is the one the bake uses. GL-free.
//
// Unless the user names a texel size or a texel budget, the texel edge is
//   t = min(kRoomTexelSize, √(A / kSmallSceneTexels)),   A = Σ_i A_i·s_i²
// (A_i the world area of static instance i, s_i its lightmapScale): 5 cm on a room's walls,
// floor and tables (a shadow's penumbra or a corner's darkening spans several texels), and finer
// on a small scene, which still gets 16,384 texels. Then the total is capped: where A / t²
// would exceed maxTexels, t grows to √(A / maxTexels), with a note saying so. The cap, 2^19
// texels, is what a default bake on a 2-core machine does in 3 minutes on a large interior (the
// Šibenik cathedral, 7,229 m²: 11.8 cm texels, whose indirect frame is 4.85% off a converged
// trace against 4.73% at 2^20 texels and 8.3 cm, which took 303 s; docs/real_scenes.md).
#pragma once

#include <cstdint>
#include <string>

namespace bounce {

inline constexpr float kRoomTexelSize = 0.05f;         // m, the default's coarsest texel edge
inline constexpr int kSmallSceneTexels = 16384;        // texels a small scene still gets
inline constexpr int64_t kDefaultMaxTexels = 1 << 19;  // cap on A / t² (524,288 texels)

struct TexelDensityRequest {
  float texelSize = 0.0f;                 // m; > 0 names the texel edge
  int texelBudget = 0;                    // > 0 (and no texelSize): t = √(A / texelBudget)
  int64_t maxTexels = kDefaultMaxTexels;  // cap on A / t², ≥ 1
};

struct TexelDensity {
  float texelSize = 0.0f;  // m
  std::string rule;        // how it was chosen, one phrase ("5 cm, the room default", …)
  std::string note;        // non-empty when the cap coarsened the texels: why, and what to do
};

// `weightedArea` = Σ A_i·s_i² in m² (> 0). Throws std::invalid_argument for a request that makes
// no sense (negative or non-finite size, budget < 0, maxTexels < 1).
TexelDensity chooseTexelDensity(double weightedArea, const TexelDensityRequest& request);

}  // namespace bounce
