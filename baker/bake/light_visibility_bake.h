// Bakes the static lights' visibility per lightmap texel (bake_folder/light_visibility.h): for
// every covered texel and every static area light l of scene/area_lights.h,
//   V_l = Σ_k w_k·vis(x_k, y_k) / Σ_k w_k,   w_k = max(n·(y_k − x_k), 0)·cosθ_y / r⁴,
// a ratio estimator of E_shadowed / E_unshadowed over `samplesPerLight` pairs (x_k, y_k): x_k
// cycles through the texel's sample points (texel_coverage.h, after the leak guard), y_k is
// stratified over the light's area (one stratum of its area CDF per sample, a Cranley–Patterson
// rotation per texel and light), and vis is one occlusion ray through the ray kernel. w_k is
// the point-to-point form-factor kernel, so each pair counts for the irradiance it brings; the
// unshadowed E_l ≈ lum(L_l)·A_l·Σ w_k / M ranks the lights for the texel's slots.
//
// A static punctual light (Scene::lights; not Light::mobility dynamic, not bakeDirect) has one
// position or direction, so its pairs are the texel's sample points x_k themselves (at most
// min(M, points)), with w_k = cosθ_x·falloff/r² (point, spot; spotFalloff of light_falloff.h) or
// cosθ_x (directional), vis a ray towards the light (unbounded for a directional light), and
// E = lum(I or E⊥)·Σ w_k / n. Area and punctual lights compete for the same slots by E.
//
// Each texel is computed from its own keys (seed, texel, light): the result does not depend on
// the thread count, nor on the tiles the work is cut into (tile_work.h). Texels without sample
// points (uncovered padding, or invalid after the leak guard) take a neighbour's record
// (fillVisibility), as the lightmap dilates.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "bake/tile_work.h"
#include "bake_folder/light_visibility.h"
#include "scene/area_lights.h"

namespace bounce {

class RayKernel;
class StageProgress;
struct TexelCoverage;

struct VisibilityTexels;
struct TexelPoint;

struct VisibilityBakeSettings {
  bool enabled = true;       // bake it when the scene has static area lights
  int samplesPerLight = 64;  // M: σ(V) ≤ 1/(2√M) per texel for unstratified pairs
  uint32_t seed = 0;
  int threads = 0;  // 0: all cores
  // Rows of texels done (total: the coverage's rows) and whether to stop, as for the
  // irradiance (texel_irradiance.h); null: neither.
  StageProgress* progress = nullptr;
  // The tiles to compute (all texels by default); the others keep the empty record.
  TileWork work;
  // Called with each tile of `work` once its texels are in `out`, as for the irradiance
  // (texel_irradiance.h); may be empty.
  std::function<void(uint32_t tile, const VisibilityTexels& out)> tileDone;
};

// What the stage computes, per texel: the map, and what its report is summed from.
struct VisibilityTexels {
  BakedVisibility map;
  std::vector<uint32_t> rays;  // occlusion rays traced
  // Σ of the unshadowed irradiance estimates of the lights that reach the texel (luminance,
  // W/m²), and the part of it the kOtherLights slot holds.
  std::vector<double> irradiance, otherIrradiance;
};

struct VisibilityBakeReport {
  uint32_t lights = 0;            // static area lights
  uint32_t punctualLights = 0;    // the scene's punctual lights (the static ones are baked)
  uint64_t rays = 0;              // occlusion rays traced
  uint64_t texelsWithLight = 0;   // covered texels some light reaches
  uint64_t texelsOverSlots = 0;   // of those, reached by more than kVisibilitySlots lights
  double otherLightsShare = 0.0;  // Σ E of lights in the "every other" slot / Σ E of all
  double seconds = 0.0;
};

// `lights` must hold the static lights first (scene/area_lights.h); only those are baked.
// `punctual` is Scene::lights (all of them: the map names light i as lightCount + i).
VisibilityTexels bakeVisibilityTexels(const AreaLightSet& lights, std::span<const Light> punctual,
                                      const RayKernel& kernel, const TexelCoverage& coverage,
                                      const VisibilityBakeSettings& settings);

// The estimate above for one set of surface points (a texel's, a triangle corner's): the
// lights' (light, V) slots, the rays traced and the unshadowed irradiance summed over the lights
// (luminance, W/m²) with the part the kOtherLights slot holds. Light l's pairs are drawn from
// the key hashKeys(seed ^ salt, index, l), so a set's result depends only on its own keys.
struct PointSetVisibility {
  TexelVisibility record;
  uint32_t rays = 0;
  double irradiance = 0.0, otherIrradiance = 0.0;
};
PointSetVisibility estimatePointSetVisibility(const AreaLightSet& lights,
                                              std::span<const Light> punctual,
                                              const RayKernel& kernel,
                                              std::span<const TexelPoint> points, uint32_t salt,
                                              uint32_t seed, uint32_t index, int samplesPerLight);

// Whether the visibility stage has anything to bake: a static area light or a static punctual
// light whose direct light is drawn live.
bool hasBakeableVisibility(const AreaLightSet& lights, std::span<const Light> punctual);

// The report's counts from the texels, whichever tiles computed them (seconds left 0).
VisibilityBakeReport summariseVisibility(const VisibilityTexels& texels);

// Every tile at once: the map, with its report.
BakedVisibility bakeLightVisibility(const AreaLightSet& lights, std::span<const Light> punctual,
                                    const RayKernel& kernel, const TexelCoverage& coverage,
                                    const VisibilityBakeSettings& settings,
                                    VisibilityBakeReport& report);

// Every texel with filled == 0 takes the record of a filled 4-neighbour (the first of left,
// right, up, down; of the same chart label first when `labels` is given), ring by ring, until
// none is left that touches a filled one. With `labels`, a chart texel its own chart cannot fill
// (a chart without one texel that kept points: a strip inside a wall, seen only where two faces
// meet at a multisampled edge) is dark to every light (one kOtherLights slot, V = 0), never
// another chart's: a slot-less record reads V = 1, and a neighbour across a thin wall is the lit
// side's. Only the padding (label 0) then takes a neighbouring chart's record.
void fillVisibility(BakedVisibility& visibility, std::vector<uint8_t> filled,
                    const std::vector<uint32_t>* labels);

}  // namespace bounce
