// The reference renderer: path-traced camera images in linear radiance, W/(sr·m²), the
// ground truth the forward renderer and the baker are measured against.
// Pixels are box-filtered (uniform jitter over the pixel from the sampler's dimension 0).
// Parallel over 16×16 tiles with TBB; every pixel's samples are taken in order with its own
// sampler, so the image depends only on (scene, camera, size, settings.seed, spp), never on
// the thread count.
#pragma once

#include <cstdint>

#include "image/image.h"
#include "ray/ray_kernel.h"
#include "scene/scene.h"
#include "scene/world_geometry.h"
#include "trace/trace_settings.h"

namespace bounce {

// The primary ray through film position (x, y) in pixels (origin top-left, x right, y down)
// of a width × height image; the camera looks down its local −Z with +Y up, yfov vertical,
// aspect = width / height.
Ray cameraRay(const Camera& camera, int width, int height, float x, float y);

struct CameraRender {
  Image radiance;        // per-pixel mean, W/(sr·m²)
  Image sampleVariance;  // per-pixel unbiased sample variance of one sample's radiance
  uint64_t samples = 0;  // camera paths traced
  // Samples whose estimate was non-finite (NaN/inf from bad scene data) and entered the
  // pixel's mean as black (PathTracer::Li): each one biases its pixel low. Counted per tile,
  // summed in tile order.
  uint64_t nonFiniteSamples = 0;
  double seconds = 0.0;  // wall time
  int threads = 0;       // threads the arena ran with
};

CameraRender traceCamera(const Scene& scene, const WorldGeometry& geometry, const RayKernel& kernel,
                         const Camera& camera, int width, int height,
                         const TraceSettings& settings);

inline Image renderCamera(const Scene& scene, const WorldGeometry& geometry,
                          const RayKernel& kernel, const Camera& camera, int width, int height,
                          const TraceSettings& settings) {
  return traceCamera(scene, geometry, kernel, camera, width, height, settings).radiance;
}

}  // namespace bounce
