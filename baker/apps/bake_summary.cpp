#include "bake_summary.h"

#include <cstdio>

#include "image/image_io.h"
#include "pipeline/bake_memory.h"
#include "pipeline/scene_bake.h"
#include "trace/sampling.h"

namespace bounce {

void writeBakeAndReport(SceneBake& baked, const BakeOutput& out) {
  for (const std::string& note : baked.notes)
    std::fprintf(stderr, "bounce-bake: note: %s\n", note.c_str());
  BakeManifest::Measured& measured = baked.folder.manifest.measured;
  measured.seconds.load = out.loadSeconds;
  measured.seconds.total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - out.start).count();
  writeBake(out.folder, baked.folder);
  if (!out.png.empty()) {
    // A white Lambertian surface's radiance E/π, tone-mapped: what the map looks like.
    Image radiance = baked.folder.irradiance;
    for (glm::vec3& p : radiance.pixels) p *= kInvPi;
    writePng(out.png, radiance, out.exposure);
  }
  const BakeManifest& manifest = baked.folder.manifest;
  const BakeManifest::Atlas& atlas = manifest.atlas;
  std::fprintf(stderr,
               "bounce-bake: %s: atlas %dx%d (%d charts, %.0f%% used, texel %.4g m), %llu "
               "texels, %.0f spp mean, estimated error of the map mean %.2f%% p95 %.2f%% "
               "luminance-weighted %.2f%% (per "
               "texel before filters %.2f%% / %.2f%%), %.2f Mrays/s, "
               "%.2f s (irradiance %.2f s), memory %s (estimated %s) -> %s\n",
               out.scene.filename().string().c_str(), atlas.width, atlas.height, atlas.charts,
               100.0 * atlas.utilisation, atlas.texelSize,
               static_cast<unsigned long long>(baked.coveredTexels), manifest.samples.perTexelMean,
               100.0 * manifest.estimatedError.mean, 100.0 * manifest.estimatedError.p95,
               100.0 * manifest.estimatedError.luminanceWeighted,
               100.0 * manifest.estimatedError.beforeFiltersMean,
               100.0 * manifest.estimatedError.beforeFiltersP95, measured.raysPerSecond * 1e-6,
               measured.seconds.total, measured.seconds.irradiance,
               formatBytes(baked.measuredPeakBytes).c_str(),
               formatBytes(baked.estimatedPeakBytes).c_str(), out.folder.string().c_str());
  const auto nonFinite = static_cast<unsigned long long>(manifest.samples.nonFinite);
  if (nonFinite > 0)
    std::fprintf(stderr,
                 "bounce-bake: warning: %llu samples were non-finite (NaN or infinite scene data "
                 "in %s?) and counted as black: the affected texels are biased low\n",
                 nonFinite, out.scene.string().c_str());
}

}  // namespace bounce
