// Baked visibility of the static lights (Unreal's stationary-light shadowing, Unity's
// shadowmask): per lightmap texel, the fraction V ∈ [0, 1] of each static light's unshadowed
// irradiance that reaches the texel's surface,
//   V_l = ∫ E_l(x, y) vis(x, y) / ∫ E_l(x, y)   over the texel's covered area x and light l's y
// (for a point, spot or directional light y is its one position or direction), so that at run
// time the shader's exact unshadowed irradiance E_l(p) times V_l is the shadowed irradiance.
// GL-free; written and read by the bake folder (visibility.bin).
//
// Light l names, for l < lightCount, static area light l (scene/area_lights.h order); for
// lightCount ≤ l < lightCount + punctualCount, the scene's punctual light l − lightCount
// (Scene::lights order; the dynamic ones and those whose direct light is baked are never named).
//
// A texel holds kVisibilitySlots (light, V) pairs, the lights that bring it the most unshadowed
// irradiance first. A texel reached by more lights names the first kVisibilitySlots − 1 and
// gives its last slot to kOtherLights: the irradiance-weighted visible fraction of all the
// others, V_rest = Σ E_l V_l / Σ E_l, which makes their summed shadowed irradiance exact at the
// texel's samples (and off only where their irradiance ratios change within a texel). A light a
// texel does not name, with no kOtherLights slot, brought the texel no irradiance: V = 1.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace bounce {

inline constexpr int kVisibilitySlots = 4;
inline constexpr uint16_t kNoLight = 0xffff;      // an empty slot
inline constexpr uint16_t kOtherLights = 0xfffe;  // every static light the texel does not name

struct TexelVisibility {
  std::array<uint16_t, kVisibilitySlots> light{kNoLight, kNoLight, kNoLight, kNoLight};
  std::array<float, kVisibilitySlots> visible{1.0f, 1.0f, 1.0f, 1.0f};  // V, in [0, 1]
  bool operator==(const TexelVisibility&) const = default;
};

// V of static light `light` (its index above) at one texel as the forward shader reads it
// (shaders/baked_visibility.glsl, texelVisibility with the shared slot): its own slot's V, else
// the "every other light" slot's, else 1.
inline float visibleFraction(const TexelVisibility& texel, uint16_t light) {
  float other = 1.0f;
  for (std::size_t s = 0; s < static_cast<std::size_t>(kVisibilitySlots); ++s) {
    if (texel.light[s] == light) return texel.visible[s];
    if (texel.light[s] == kOtherLights) other = texel.visible[s];
  }
  return other;
}

struct BakedVisibility {
  int width = 0, height = 0;            // the lightmap's
  uint32_t lightCount = 0;              // the scene's static area lights (scene/area_lights.h)
  uint32_t punctualCount = 0;           // the scene's punctual lights (Scene::lights, all)
  std::vector<TexelVisibility> texels;  // width × height, rows top first

  // The index light l of Scene::lights has in the texels' slots.
  uint16_t punctualIndex(std::size_t l) const { return static_cast<uint16_t>(lightCount + l); }
  uint32_t indexCount() const { return lightCount + punctualCount; }
};

}  // namespace bounce
