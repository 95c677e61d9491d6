#include "render/render_mode.h"

#include <array>

namespace bounce {
namespace {

constexpr std::array kModes = {RenderMode::Full,         RenderMode::Direct,   RenderMode::Indirect,
                               RenderMode::Lightmap,     RenderMode::Charts,   RenderMode::Vpl,
                               RenderMode::VplClamp,     RenderMode::Error,    RenderMode::Validity,
                               RenderMode::TexelDensity, RenderMode::Cascades, RenderMode::Cost};

}  // namespace

std::string_view renderModeName(RenderMode mode) {
  switch (mode) {
    case RenderMode::Direct:
      return "direct";
    case RenderMode::Full:
      return "full";
    case RenderMode::Indirect:
      return "indirect";
    case RenderMode::Lightmap:
      return "lightmap";
    case RenderMode::Charts:
      return "charts";
    case RenderMode::Vpl:
      return "vpl";
    case RenderMode::VplClamp:
      return "vpl-clamp";
    case RenderMode::Error:
      return "error";
    case RenderMode::Validity:
      return "validity";
    case RenderMode::TexelDensity:
      return "texel-density";
    case RenderMode::Cascades:
      return "cascades";
    case RenderMode::Cost:
      return "cost";
  }
  return "direct";
}

bool renderModeNeedsBake(RenderMode mode) {
  return mode != RenderMode::Direct && mode != RenderMode::Cascades && mode != RenderMode::Cost;
}

bool renderModeNeedsVpls(RenderMode mode) {
  return mode == RenderMode::Vpl || mode == RenderMode::VplClamp;
}

bool renderModeNeedsErrorMap(RenderMode mode) {
  return mode == RenderMode::Error || mode == RenderMode::Validity;
}

std::optional<RenderMode> parseRenderMode(std::string_view name) {
  for (const RenderMode mode : kModes)
    if (renderModeName(mode) == name) return mode;
  return std::nullopt;
}

std::vector<std::string> renderModeNames() {
  std::vector<std::string> names;
  for (const RenderMode mode : kModes) names.emplace_back(renderModeName(mode));
  return names;
}

}  // namespace bounce
