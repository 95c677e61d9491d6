// What the lit pass draws. Direct light is drawn live (punctual and area lights, shadowed);
// indirect light comes from the lightmap (static surfaces) or the VPLs (dynamic instances; every
// surface in the vpl modes).
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
  Vpl,       // indirect light of every surface from the VPLs, ρ/π·E_vpl (needs a bake with VPLs)
  VplClamp,  // (lum E_vpl, lum E_removed, 0)/π: the VPLs and what their clamp removed, white
             // surfaces (needs VPLs; bounce-render's clamp report reads it)
  Error,     // each texel's estimated relative error as a false colour (bake_folder/texel_error.h;
             // needs a bake with error.exr)
  Validity,  // each texel sampled, filled from neighbours or padding (bake_folder/texel_error.h;
             // needs a bake with error.exr)
  TexelDensity,  // lightmap texels per metre against the bake's texel size as a false colour, ×
                 // a checker of texels (render/view_mode_colours.h; needs a bake)
  Cascades,      // the directional light's shadow cascade index as a false colour
                 // (render/view_mode_colours.h; no bake needed)
  Cost,          // what each pixel evaluated, shading as Full (Direct without a bake): the
                 // counts of lights, VPLs and shadow-map taps as R, G, B (shaders/cost.glsl;
                 // render/cost_view.h draws them in false colour; no bake needed)
};

// Whether the mode reads the lightmap, its layout or the VPLs (and so needs a bake).
bool renderModeNeedsBake(RenderMode mode);
// Whether the mode draws every surface from the VPLs (and so needs a bake with VPLs).
bool renderModeNeedsVpls(RenderMode mode);
// Whether the mode shows the bake's error map (and so needs a bake with error.exr).
bool renderModeNeedsErrorMap(RenderMode mode);

// "direct", …: the names the tools' --mode accepts.
std::string_view renderModeName(RenderMode mode);
std::optional<RenderMode> parseRenderMode(std::string_view name);
std::vector<std::string> renderModeNames();

}  // namespace bounce
