// Shadow quality against speed: for shadow-map resolutions 512…4096 and each filter, the
// Cornell box's direct light (area light, soft shadows) rendered offscreen, timed per frame, and
// compared with a path-traced reference; writes CSV for docs/charts/plot_soft_shadows.py.
//
//   bench_soft_shadows REFERENCE.exr STD_ERROR.exr [--size N] [--frames F] [--out FILE.csv]
//
// REFERENCE.exr and STD_ERROR.exr: `bounce-trace content/cornell_box/cornell_box.gltf
// --direct-only --width N --height N --spp S --out REFERENCE.exr --std-error STD_ERROR.exr`.
// Columns: resolution (texels per side), filter (hard: one comparison; soft: 16-tap Poisson PCF
// for punctual maps, percentage-closer soft shadows for area lights), ms_per_frame (median of F
// frames after one warm-up, render + readback, at N×N), mare (mean |f − r|/(r + 0.01) over
// non-emitter pixels), penumbra_share, umbra_share.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include "gl/context.h"
#include "gl/shader.h"
#include "image/image_io.h"
#include "render/forward_renderer.h"
#include "scene/load.h"
#include "shadow_comparison.h"
#include "trace/camera_render.h"

using namespace bounce;

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(
        stderr,
        "usage: bench_soft_shadows REFERENCE.exr STD_ERROR.exr [--size N] [--frames F] [--out "
        "FILE.csv]\n");
    return 2;
  }
  int size = 256, frames = 5, supersample = 2;
  std::string out = "shadows.csv";
  for (int i = 3; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--size")
      size = std::stoi(argv[i + 1]);
    else if (flag == "--frames")
      frames = std::stoi(argv[i + 1]);
    else if (flag == "--out")
      out = argv[i + 1];
    else {
      std::fprintf(stderr, "bench_soft_shadows: unknown option %s\n", flag.c_str());
      return 2;
    }
  }
  try {
    const Scene scene = loadScene(BOUNCE_SOURCE_DIR "/content/cornell_box/cornell_box.gltf");
    const Camera camera = scene.cameras.front();
    CameraRender reference;
    reference.radiance = readExr(argv[1]);
    const Image stdError = readExr(argv[2]);
    if (reference.radiance.width != size || reference.radiance.height != size) {
      std::fprintf(stderr, "bench_soft_shadows: %s is %dx%d, expected %dx%d (--size)\n", argv[1],
                   reference.radiance.width, reference.radiance.height, size, size);
      return 1;
    }
    // compareToReference wants the per-sample variance and spp: σ² = var/spp with spp = 1.
    reference.sampleVariance = Image(size, size);
    for (std::size_t i = 0; i < stdError.pixels.size(); ++i)
      reference.sampleVariance.pixels[i] = stdError.pixels[i] * stdError.pixels[i];

    const auto context = gl::createOffscreenContext(std::nullopt);
    using Clock = std::chrono::steady_clock;
    // Median of F frames after one warm-up (shader JIT, map allocation): the machine is shared,
    // and the median ignores the frames another process slowed down.
    const auto timeFrames = [&](ForwardRenderer& renderer, Image& image) {
      image = renderer.renderImage(camera, size, size);
      std::vector<double> ms;
      for (int f = 0; f < frames; ++f) {
        const auto start = Clock::now();
        image = renderer.renderImage(camera, size, size);
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
      }
      std::sort(ms.begin(), ms.end());
      return ms[ms.size() / 2];
    };
    RendererSettings none;
    none.shadows.enabled = false;
    ForwardRenderer unshadowedRenderer(scene, gl::shaderDirectory(), none);
    Image unshadowedFrame;
    const double unshadowedMs = timeFrames(unshadowedRenderer, unshadowedFrame);
    const Image unshadowedHi =
        unshadowedRenderer.renderImage(camera, size * supersample, size * supersample);
    const std::vector<bool> mask = test::nonEmitterPixels(scene, unshadowedHi, supersample);
    const Image unshadowed = test::boxDownsample(unshadowedHi, supersample);
    const test::ShadowError base =
        test::compareToReference(unshadowed, reference, mask, unshadowed, 1);

    FILE* csv = std::fopen((out + ".tmp").c_str(), "w");
    if (!csv) {
      std::fprintf(stderr, "bench_soft_shadows: %s: cannot write\n", out.c_str());
      return 1;
    }
    std::fprintf(csv, "resolution,filter,ms_per_frame,mare,penumbra_share,umbra_share\n");
    std::fprintf(csv, "0,none,%.3f,%.5f,%.3f,%.3f\n", unshadowedMs, base.meanAbsRelative,
                 base.penumbraShare, base.umbraShare);
    std::fprintf(stderr, "no shadows: %.1f ms/frame, MARE %.4f\n", unshadowedMs,
                 base.meanAbsRelative);
    for (const int resolution : {512, 1024, 2048, 4096}) {
      for (const ShadowFilter filter : {ShadowFilter::Hardware, ShadowFilter::Poisson}) {
        RendererSettings settings;
        settings.shadows.resolution = resolution;
        settings.shadows.filter = filter;
        ForwardRenderer renderer(scene, gl::shaderDirectory(), settings);
        Image frame;
        const double ms = timeFrames(renderer, frame);
        const Image hi = renderer.renderImage(camera, size * supersample, size * supersample);
        const test::ShadowError e = test::compareToReference(test::boxDownsample(hi, supersample),
                                                             reference, mask, unshadowed, 1);
        const char* name = filter == ShadowFilter::Hardware ? "hard" : "soft";
        std::fprintf(csv, "%d,%s,%.3f,%.5f,%.3f,%.3f\n", resolution, name, ms, e.meanAbsRelative,
                     e.penumbraShare, e.umbraShare);
        std::fprintf(stderr, "%d %s: %.1f ms/frame, MARE %.4f (penumbra %.2f, umbra %.2f)\n",
                     resolution, name, ms, e.meanAbsRelative, e.penumbraShare, e.umbraShare);
      }
    }
    std::fclose(csv);
    std::rename((out + ".tmp").c_str(), out.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_soft_shadows: %s\n", e.what());
    return 1;
  }
  return 0;
}
