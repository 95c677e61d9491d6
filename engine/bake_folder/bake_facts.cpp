#include "bake_folder/bake_facts.h"

#include <chrono>
#include <cstdio>
#include <system_error>

namespace bounce {
namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char line[160];
  std::snprintf(line, sizeof line, pattern, a, b, c);
  return line;
}

}  // namespace

BakeFacts bakeFacts(const Bake& bake, const std::filesystem::path& dir) {
  BakeFacts f;
  f.dir = dir;
  f.atlasWidth = bake.layout.width;
  f.atlasHeight = bake.layout.height;
  f.texelSize = bake.layout.texelSize;
  f.vpls = bake.vpls ? bake.vpls->size() : 0;
  f.probes = bake.probes ? bake.probes->probes.size() : 0;
  f.probeGrids = bake.probes ? bake.probes->grids.size() : 0;
  f.bakedAreaLights = bake.visibility ? bake.visibility->lightCount : 0;
  f.punctualLights = bake.visibility ? bake.visibility->punctualCount : 0;
  f.errorMap = bake.relativeError.has_value();
  // bounce-bake's manifests hash their settings; a hand-made one (tests, tools) records none of
  // these figures, and zeros would be shown as if measured.
  const BakeManifest& m = bake.manifest;
  if (!m.settingsHash.empty()) {
    // The atlas figures from layout.bin, which its hash guards (bake.json repeats them).
    f.utilisation = bake.layout.utilisation;
    f.charts = bake.layout.chartCount;
    f.samplesPerTexel = m.samples.perTexelMean;
    f.errorMean = m.estimatedError.mean;
    f.errorP95 = m.estimatedError.p95;
    f.errorTarget = m.estimatedError.target;
    f.bakeSeconds = m.measured.seconds.total;
  }
  std::error_code error;
  const auto written = std::filesystem::last_write_time(dir / "bake.json", error);
  if (!dir.empty() && !error)
    f.ageSeconds =
        std::chrono::duration<double>(std::filesystem::file_time_type::clock::now() - written)
            .count();
  return f;
}

std::string ageText(double seconds) {
  if (seconds < 90.0) return format("%.0f s", seconds);
  if (seconds < 90.0 * 60.0) return format("%.0f min", seconds / 60.0);
  if (seconds < 36.0 * 3600.0) return format("%.0f h", seconds / 3600.0);
  return format("%.0f days", seconds / 86400.0);
}

std::vector<std::string> bakeFactLines(const BakeFacts& f) {
  std::vector<std::string> lines{f.dir.string()};
  std::string atlas = format("atlas %.0f x %.0f texels", f.atlasWidth, f.atlasHeight);
  if (f.utilisation) atlas += format(", %.0f%% used", 100.0 * *f.utilisation);
  if (f.charts) atlas += format(", %.0f charts", static_cast<double>(*f.charts));
  lines.push_back(atlas);
  lines.push_back(format("texel %.3g cm", 100.0 * f.texelSize));
  if (f.samplesPerTexel)
    lines.push_back(format("%.0f samples per texel (mean)", *f.samplesPerTexel));
  if (f.errorMean && f.errorP95)
    lines.push_back(format("estimated error %.1f%% mean, %.1f%% p95", 100.0 * *f.errorMean,
                           100.0 * *f.errorP95) +
                    (f.errorTarget ? format(" (target %.1f%%)", 100.0 * *f.errorTarget) : ""));
  if (f.vpls > 0) lines.push_back(format("%.0f VPLs", static_cast<double>(f.vpls)));
  if (f.probes > 0)
    lines.push_back(format("%.0f probes around %.0f instances without a lightmap",
                           static_cast<double>(f.probes), static_cast<double>(f.probeGrids)));
  if (f.bakedAreaLights + f.punctualLights > 0)
    lines.push_back(format("baked visibility of %.0f area and %.0f punctual lights",
                           static_cast<double>(f.bakedAreaLights),
                           static_cast<double>(f.punctualLights)));
  if (f.bakeSeconds) lines.push_back(format("baked in %.1f s", *f.bakeSeconds));
  if (f.ageSeconds) lines.push_back("written " + ageText(*f.ageSeconds) + " ago");
  return lines;
}

}  // namespace bounce
