// What the lit pass draws. Direct light is drawn live (punctual and area lights, shadowed);
// modes that add baked or VPL indirect light slot in here.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bounce {

enum class RenderMode {
  Direct,    // direct light only (emission + punctual + area lights), whether or not a bake exists
  Full,      // direct light + baked indirect ρ/π·E on static surfaces (needs a bake)
  Indirect,  // only the baked indirect ρ/π·E (needs a bake; compare: bounce-trace --indirect-only)
  Lightmap,  // the baked irradiance itself, shown as E/π: a white (ρ = 1) surface (needs a bake)
  Charts,    // lightmap charts, each its colour, × a checker of texels (needs a bake)
};

// Whether the mode reads the lightmap (and so needs a bake).
bool renderModeNeedsBake(RenderMode mode);

// "direct", …: the names the tools' --mode accepts.
std::string_view renderModeName(RenderMode mode);
std::optional<RenderMode> parseRenderMode(std::string_view name);
std::vector<std::string> renderModeNames();

}  // namespace bounce
