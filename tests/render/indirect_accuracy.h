// The renderer's baked indirect light against the reference path tracer, as docs/renderer.md
// ("Baked light") measures it: bake a scene in-process with bakeScene, draw `--mode indirect`,
// trace `--indirect-only` with the same camera, and compare over the pixels that see one flat piece
// of a static, non-emissive surface (pixel_surfaces.h). Used by the CI-sized test and the
// full-size benchmark (tests/bench/bench_indirect_accuracy.cpp).
//
// Error: mean over the masked pixels of |Y_r − Y_t| / Y_t, Y the luminance of rendered (r) and
// traced (t) radiance. The trace has its own noise: with per-pixel standard error σ_i of Y_t,
// the triangle inequality bounds what it adds to the mean by mean(E|N(0, σ_i)|/Y_t) =
// √(2/π)·mean(σ_i/Y_t) (σ_i bounded above by Σ_c w_c σ_c from the per-channel variances), which
// is reported as `referenceNoise`.
#pragma once

#include <cmath>
#include <vector>

#include "bake_folder/bake_folder.h"
#include "gl/shader.h"
#include "image/image.h"
#include "image/luminance.h"
#include "pipeline/scene_bake.h"
#include "pixel_surfaces.h"
#include "ray/ray_kernel.h"
#include "render/forward_renderer.h"
#include "scene/world_geometry.h"
#include "trace/camera_render.h"
#include "trace/sampling.h"

namespace bounce::test {

// bounce-bake's defaults without VPLs: what the comparisons below bake with bakeScene
// (pipeline/scene_bake.h), the entry point bounce-bake calls, static-scene step included.
inline SceneBakeSettings lightmapOnlySettings() {
  SceneBakeSettings settings;
  settings.vpls = 0;
  return settings;
}

struct IndirectComparison {
  Mask mask;
  std::size_t pixels = 0;        // compared
  double meanAbsRelError = 0.0;  // luminance, see above
  double referenceNoise = 0.0;   // √(2/π)·mean(σ_i/Y_t)
  double meanRelStdError = 0.0;  // mean(σ_i/Y_t)
  double bias = 0.0;             // mean (Y_r − Y_t)/Y_t
};

struct Reference {
  Image radiance;  // --indirect-only, W/(sr·m²)
  Image stdError;  // per pixel and channel, of the mean
};

// The path tracer's image of `paths` (IndirectOnly for the lightmap, DirectOnly for the direct
// light) with each pixel's standard error.
inline Reference traceReference(const Scene& scene, const Camera& camera, int width, int height,
                                int spp, PathSet paths, uint32_t seed = 1) {
  const WorldGeometry geometry = flatten(scene);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  TraceSettings trace;
  trace.spp = spp;
  trace.paths = paths;
  trace.seed = seed;
  const CameraRender traced = traceCamera(scene, geometry, *kernel, camera, width, height, trace);
  Reference r{traced.radiance, Image(width, height)};
  for (std::size_t i = 0; i < r.radiance.pixels.size(); ++i)
    r.stdError.pixels[i] = glm::sqrt(traced.sampleVariance.pixels[i] / static_cast<float>(spp));
  return r;
}

inline Reference traceIndirectReference(const Scene& scene, const Camera& camera, int width,
                                        int height, int spp, uint32_t seed = 1) {
  return traceReference(scene, camera, width, height, spp, PathSet::IndirectOnly, seed);
}

// The renderer's frame as the tracer's pixels see it: drawn at k× the resolution, one sample per
// pixel, and box-filtered, so each pixel averages radiance over its area (multisampling alone
// shades once per pixel). Needs a current GL context.
inline Image renderAreaAveraged(ForwardRenderer& renderer, const Camera& camera, int width,
                                int height, int k) {
  return boxDownsample(renderer.renderImage(camera, k * width, k * height, 1), k);
}

// --mode indirect; needs a current GL context.
inline Image renderIndirect(const Scene& scene, const Bake& bake, const Camera& camera, int width,
                            int height) {
  RendererSettings settings;
  settings.mode = RenderMode::Indirect;
  ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, &bake);
  return renderer.renderImage(camera, width, height);
}

inline IndirectComparison compareIndirect(const Scene& scene, const Camera& camera,
                                          const Image& rendered, const Reference& reference) {
  IndirectComparison c;
  const WorldGeometry geometry = flatten(scene);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  const PixelSurfaces surfaces =
      findPixelSurfaces(geometry, *kernel, camera, rendered.width, rendered.height);
  c.mask = staticSurfaceMask(scene, geometry, surfaces);
  double sumError = 0.0, sumSigma = 0.0, sumBias = 0.0;
  for (std::size_t i = 0; i < c.mask.keep.size(); ++i) {
    const double yt = luminance(reference.radiance.pixels[i]);
    if (!c.mask.keep[i] || !(yt > 0.0)) {
      c.mask.keep[i] = 0;
      continue;
    }
    const double yr = luminance(rendered.pixels[i]);
    const glm::vec3 s = reference.stdError.pixels[i];
    sumError += std::abs(yr - yt) / yt;
    sumBias += (yr - yt) / yt;
    sumSigma += luminance(glm::dvec3(s)) / yt;
    ++c.pixels;
  }
  if (c.pixels > 0) {
    const double n = static_cast<double>(c.pixels);
    c.meanAbsRelError = sumError / n;
    c.bias = sumBias / n;
    c.meanRelStdError = sumSigma / n;
    c.referenceNoise = std::sqrt(2.0 / 3.14159265358979) * c.meanRelStdError;
  }
  return c;
}

}  // namespace bounce::test
