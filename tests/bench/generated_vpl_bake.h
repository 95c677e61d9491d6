// A bake that holds only VPLs, generated in-process by the baker's light tracer over the scene's
// static instances (bounce-bake's rule with the error target off, so `cap` is the count), with
// bounce-bake's clamp distance r = sqrt(A/(πN)) in its manifest and a 1×1 black lightmap (the
// vpl mode never reads it). Shared by bench_vpl and bench_vpl_error.
#pragma once

#include <cstdint>

#include "bake_folder/bake_folder.h"
#include "bake_folder/vpl_clamp.h"
#include "ray/ray_kernel.h"
#include "scene/static_scene.h"
#include "scene/world_geometry.h"
#include "vpl/vpl_generate.h"

namespace bounce::test {

inline Bake generatedVplBake(const Scene& scene, int cap, uint32_t seed = 0) {
  const Scene statics = staticScene(scene);
  const WorldGeometry geometry = flatten(statics);
  const auto kernel = makeRayKernel(geometry, RayBackend::Bvh);
  VplSettings settings;
  settings.maxVpls = cap;
  settings.relativeError = 0.0f;
  settings.seed = seed;
  Bake b;
  b.layout.width = b.layout.height = 1;
  b.layout.texelSize = 1.0f;
  b.irradiance = Image(1, 1);
  b.vpls = generateVpls(statics, geometry, *kernel, settings).vpls;
  b.manifest.vpls =
      BakeManifest::Vpls{.count = b.vpls->size(),
                         .clampDistance = vplClampDistance(surfaceArea(geometry), b.vpls->size())};
  return b;
}

}  // namespace bounce::test
