#include "pipeline/bake_memory.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "bake/texel_coverage.h"
#include "bake_folder/gather.h"
#include "bake_folder/light_visibility.h"
#include "bake_folder/lightmap_layout.h"
#include "bake_folder/vpl.h"
#include "pipeline/scene_bake_settings.h"
#include "scene/area_lights.h"
#include "scene/scene.h"

namespace bounce {
namespace {

// The texels' arrays, bytes. Those the bake sizes by the atlas add up to about 156 per texel
// (irradiance 12, samples 4, error 4, covered 1, invalid 1, non-finite counts 4, chart labels 4,
// point offsets 4, the denoiser's guide 32 and its copy of the image 12, the dilation masks 2,
// the folder's lightmap and error map 24, their EXR encodings 32; for the delivered error,
// delivered_error.h, the half-sample difference 12, the first samples' mean 4 and the error per
// texel 4; the 80 more a texel the denoiser takes for the two half maps while it runs stay under
// the irradiance stage's peak: measured at 2^17 Cornell texels, 119 MB before and after), and
// what the other terms leave of a measured peak also grows with the covered texels (the leak
// guard's and the summaries' working sets) and has a fixed part (the libraries' pools). Fitted
// to the Cornell box, many_lights and the Šibenik cathedral (whose atlases are 85%, 91% and 45%
// covered); the Conference Room checks it (docs/baker.md, "Memory").
constexpr double kBytesPerAtlasTexel = 155.0;
constexpr double kBytesPerCoveredTexel = 150.0;
constexpr double kFixedBytes = 3e6;
// The cache gather (bake/irradiance_cache.h) keeps its two half maps through the final pass: per
// atlas texel their irradiance (2 × 12) and the mask (1); per static triangle its corner UVs and
// texel edge (28). (The cache pass's own gather arrays, 44 a texel while a half is traced, stay
// under the final pass's peak: the cache is no longer denoised.)
constexpr double kCacheBytesPerAtlasTexel = 25.0;
constexpr double kCacheBytesPerTriangle = 28.0;
// Per static triangle besides the kernel: the flattened world geometry (3 vertices' position,
// normal and two UVs, 3 indices, material and instance: about 3·40 + 20) and the static scene.
constexpr double kGeometryBytesPerTriangle = 140.0 + 60.0;

}  // namespace

double residentBytes() {
  std::ifstream statm("/proc/self/statm");
  double pages = 0, resident = 0;
  if (!(statm >> pages >> resident)) return 0.0;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE));
}

double peakResidentBytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0.0;
  return static_cast<double>(usage.ru_maxrss) * 1024.0;  // Linux: kilobytes
}

BakeMemoryEstimate estimateBakeMemory(const Scene& scene, const LightmapLayout& layout,
                                      double utilisation, const SceneBakeSettings& settings) {
  BakeMemoryEstimate e;
  e.resident = residentBytes();
  e.peakSoFar = peakResidentBytes();
  double triangles = 0;
  for (const Instance& instance : scene.instances)
    if (instance.mobility == Mobility::Static)
      triangles += static_cast<double>(scene.meshes[instance.mesh].indices.size() / 3);
  e.geometry = triangles * (kKernelBytesPerTriangle + kGeometryBytesPerTriangle);
  const double texels = static_cast<double>(layout.width) * static_cast<double>(layout.height);
  e.texels = kFixedBytes + texels * (kBytesPerAtlasTexel + utilisation * kBytesPerCoveredTexel);
  if (settings.gather == Gather::Cache)
    e.texels += texels * kCacheBytesPerAtlasTexel + triangles * kCacheBytesPerTriangle;
  constexpr int kPointsPerTexel = 8;  // LightmapBakeSettings::pointsPerTexel
  // The point list is allocated once for every covered texel (texel_coverage.cpp).
  e.points = utilisation * texels * kPointsPerTexel * static_cast<double>(sizeof(TexelPoint));
  if (sceneAreaLights(scene).staticCount() > 0)
    e.visibility = texels * (2.0 * sizeof(TexelVisibility) + 2 * sizeof(double));
  e.vpls = std::max(settings.vpls, 0) * 2.0 * static_cast<double>(sizeof(Vpl) + 1);
  return e;
}

std::string formatBytes(double bytes) {
  char text[32];
  if (bytes >= 1e9)
    std::snprintf(text, sizeof text, "%.2f GB", bytes * 1e-9);
  else if (bytes >= 1e6)
    std::snprintf(text, sizeof text, "%.0f MB", bytes * 1e-6);
  else
    std::snprintf(text, sizeof text, "%.0f kB", bytes * 1e-3);
  return text;
}

std::string BakeMemoryEstimate::describe() const {
  return formatBytes(peak()) + " (the peak so far " + formatBytes(peakSoFar) + "; resident now " +
         formatBytes(resident) + ", geometry and ray " + "kernel " + formatBytes(geometry) +
         ", texels " + formatBytes(texels) + ", sample points " + formatBytes(points) +
         ", visibility " + formatBytes(visibility) + ", VPLs " + formatBytes(vpls) + ")";
}

double parseMemorySize(const std::string& text) {
  std::size_t used = 0;
  double value = -1.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  const std::string unit = text.substr(used);
  double scale = 0.0;
  if (unit.empty()) scale = 1.0;
  if (unit == "k" || unit == "K") scale = 1e3;
  if (unit == "M" || unit == "m") scale = 1e6;
  if (unit == "G" || unit == "g") scale = 1e9;
  if (used == 0 || scale == 0.0 || !std::isfinite(value) || value <= 0.0)
    throw std::invalid_argument("'" + text +
                                "' is not a memory size (a positive number with k, M or G, "
                                "e.g. 512M or 4G)");
  return value * scale;
}

}  // namespace bounce
