#include "bake_folder/manifest_rules.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "bake_folder/bake_settings.h"
#include "bake_folder/vpl_clamp.h"
#include "image/luminance.h"
#include "io/load_error.h"

namespace bounce {
namespace {

bool sameReal(double found, double rule) {
  return std::abs(found - rule) <= kManifestRuleTolerance * std::abs(rule);
}

}  // namespace

void checkManifestRules(const std::filesystem::path& manifestFile, const Bake& bake,
                        const Scene& scene) {
  const BakeManifest& m = bake.manifest;
  const auto refuse = [&](const std::string& field, const std::string& why) {
    throw LoadError(manifestFile, "\"" + field + "\" is " + why + ": damaged: rebake");
  };
  // The settings are hashed as written: the seed, the caps and the targets below rest on them.
  const bool before = m.settings.lightChoice == LightChoice::ByPower &&
                      m.settingsHash == settingsHashWithoutLightChoice(m.settings);
  if (!m.settingsHash.empty() && m.settingsHash != settingsHash(m.settings) && !before)
    refuse("settingsHash", m.settingsHash + ", the settings hash to " + settingsHash(m.settings));
  if (m.estimatedError.target != m.settings.targetError)
    refuse("estimatedError.target", shortNumber(m.estimatedError.target) +
                                        ", the bake's settings.targetError is " +
                                        shortNumber(m.settings.targetError));

  // The error summary is of error.exr's estimates (the lit, unfilled ones among them): its p95 is
  // one of them and its mean lies within them; 0 and 0 where no texel was lit.
  const BakeManifest::EstimatedError& e = m.estimatedError;
  if (bake.relativeError && !(e.mean == 0.0 && e.p95 == 0.0)) {
    float lowest = kMaxRelativeError, highest = 0.0f;
    bool p95Found = false;
    for (const glm::vec3& texel : bake.relativeError->pixels) {
      if (texel.r == kNoErrorEstimate) continue;
      lowest = std::min(lowest, texel.r);
      highest = std::max(highest, texel.r);
      p95Found = p95Found || static_cast<double>(texel.r) == e.p95;
    }
    if (!p95Found)
      refuse("estimatedError.p95",
             shortNumber(e.p95) + ", not the estimate of any texel of " + "error.exr");
    if (!(lowest <= e.mean && e.mean <= highest))
      refuse("estimatedError.mean", shortNumber(e.mean) + ", outside error.exr's estimates " +
                                        shortNumber(lowest) + " .. " + shortNumber(highest));
  }

  // Samples per texel: the mean is the total over the texels with samples of their own.
  const BakeManifest::Samples& s = m.samples;
  const uint64_t valid = m.atlas.coveredTexels >= m.atlas.invalidTexels
                             ? m.atlas.coveredTexels - m.atlas.invalidTexels
                             : 0;
  const double mean = valid > 0 ? static_cast<double>(s.total) / static_cast<double>(valid) : 0.0;
  if (!sameReal(s.perTexelMean, mean))
    refuse("samples.perTexelMean", shortNumber(s.perTexelMean) + ", samples.total / (covered - " +
                                       "invalid texels) is " + shortNumber(mean));
  if (valid > 0 &&
      !(static_cast<double>(s.perTexelMin) <= mean && mean <= static_cast<double>(s.perTexelMax)))
    refuse("samples.perTexelMean", shortNumber(mean) + ", outside perTexelMin " +
                                       std::to_string(s.perTexelMin) + " .. perTexelMax " +
                                       std::to_string(s.perTexelMax));

  if (!m.vpls || !bake.vpls) return;
  const BakeManifest::Vpls& v = *m.vpls;
  // The clamp r = sqrt(A/(π·N)) of the VPLs' static surface area and count (vpl_clamp.h): 0 only
  // where there are no VPLs or no static area.
  const double rule = vplClampDistance(staticSurfaceArea(scene), bake.vpls->size());
  if (!sameReal(v.clampDistance, rule))
    refuse("vpls.clampDistance", shortNumber(v.clampDistance) +
                                     " m, the bake's rule sqrt(A/(pi N)) gives " +
                                     shortNumber(rule) + " m for the scene's static area and " +
                                     std::to_string(bake.vpls->size()) + " VPLs");
  if (v.cap != m.settings.vpls)
    refuse("vpls.cap", std::to_string(v.cap) + ", the bake's settings.vpls is " +
                           std::to_string(m.settings.vpls));
  if (v.errorTarget != m.settings.vplError)
    refuse("vpls.errorTarget", shortNumber(v.errorTarget) + ", the bake's settings.vplError is " +
                                   shortNumber(m.settings.vplError));
  // Every VPL's path was traced: a smaller count would scale --vpl-paths' flux wrongly. Only a
  // hand-made manifest (no settingsHash) leaves it 0, for the renderer to count.
  uint64_t paths = 0;
  for (const Vpl& vpl : *bake.vpls) paths = std::max<uint64_t>(paths, uint64_t{vpl.path} + 1);
  if (v.paths == 0 && m.settingsHash.empty()) return;
  if (v.paths < paths)
    refuse("vpls.paths", std::to_string(v.paths) + ", fewer than the " + std::to_string(paths) +
                             " paths the vpls file's VPLs come from");
  // The count N the generator's relative error was computed with (vpl_generate.h): with T_i
  // path i's VPL flux (luminance, W) as filed (Φ = β·ρ/N), F = Σ T_i and Q = Σ T_i², the error
  // r² = (N·Q − F²) / ((N − 1)·F²) gives N = F²(1 − r²) / (Q − r²F²). Paths without a VPL have
  // T = 0 and count only through N.
  std::vector<double> pathFlux(paths, 0.0);
  for (const Vpl& vpl : *bake.vpls) pathFlux[vpl.path] += luminance(glm::dvec3(vpl.flux));
  double f = 0.0, q = 0.0;
  for (const double t : pathFlux) f += t, q += t * t;
  const double r2 = v.relativeError * v.relativeError;
  const double n = f * f * (1.0 - r2) / (q - r2 * f * f);
  if (f > 0.0 && !(std::abs(n - static_cast<double>(v.paths)) <=
                   std::max(0.5, 1e-4 * static_cast<double>(v.paths))))
    refuse("vpls.paths", std::to_string(v.paths) + ", the vpls file's flux and " +
                             "vpls.relativeError " + shortNumber(v.relativeError) + " give " +
                             shortNumber(n) + " paths");
}

}  // namespace bounce
