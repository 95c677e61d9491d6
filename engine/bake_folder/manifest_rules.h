// bake.json's numbers that a reader uses, against the rules bounce-bake made them by: bake.json
// has no hash of its own (it holds the others'), so a number some reader takes from it (the
// renderer's VPL clamp and path count, the VPL re-trace's cap, error target and seed, the error
// view's target, the panel's samples per texel and error summary) is accepted only where
// bounce-bake could have written it for this scene and these files (docs/bake_folder.md, "What
// guards each number"). GL-free.
#pragma once

#include <filesystem>

#include "bake_folder/bake_folder.h"
#include "scene/scene.h"

namespace bounce {

// Relative difference within which a recomputed real number counts as the one the bake wrote:
// a few float steps (2^-23 ≈ 1.2e-7 each), for a float the baker computed in another order or
// with another rounding of the same doubles.
inline constexpr double kManifestRuleTolerance = 1e-5;

// Throws LoadError(manifestFile, "<field> is <value>, <what the rule gives>: damaged: rebake")
// at the first number that disagrees with its rule:
//   settingsHash          = FNV-1a of the settings (where bounce-bake wrote one; bake.json files
//                           from before settings.lightChoice: of the settings without it)
//   vpls.clampDistance    = vplClampDistance(staticSurfaceArea(scene), vpls.count) (vpl_clamp.h)
//   vpls.cap              = settings.vpls;  vpls.errorTarget = settings.vplError
//   vpls.paths            ≥ the paths the VPLs come from, and = the N that the VPLs' flux and
//                         vpls.relativeError give (the generator's error formula solved for N)
//                         (0 where the manifest is hand-made, no settingsHash: the renderer
//                         then counts the paths)
//   estimatedError.target = settings.targetError
//   estimatedError.p95    one of error.exr's texels, and .mean within their range (or both 0)
//   samples.perTexelMean  = samples.total / (atlas.coveredTexels − atlas.invalidTexels), and
//                           perTexelMin ≤ mean ≤ perTexelMax
// `bake` is what readBake read (its files already checked against their hashes and formats).
void checkManifestRules(const std::filesystem::path& manifestFile, const Bake& bake,
                        const Scene& scene);

}  // namespace bounce
