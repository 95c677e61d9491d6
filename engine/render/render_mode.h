// What the lit pass draws. Direct light is drawn live (punctual and area lights, shadowed);
// modes that add baked or VPL indirect light slot in here.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bounce {

enum class RenderMode {
  Direct,  // direct light only (emission + punctual + area lights), whether or not a bake exists
};

// "direct", …: the names the tools' --mode accepts.
std::string_view renderModeName(RenderMode mode);
std::optional<RenderMode> parseRenderMode(std::string_view name);
std::vector<std::string> renderModeNames();

}  // namespace bounce
