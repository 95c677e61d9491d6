// The VPL term's error against its frame time (docs/vpl_measurements.md, "Error against frame
// time"). Cornell box, one path-traced indirect-only reference (cached as EXR with its per-pixel
// standard error), compared as tests/render/indirect_accuracy.h does over the pixels that see one
// flat piece of a static, non-emissive surface. For each VPL cap (the baker's generator in-process,
// error target off so the cap is the count, one seed) and each of {per-cell lightcut culling
// on/off} × {VPL shadow maps on/off}, `--mode vpl` is drawn and timed; then the lightmap's point: a
// fresh bake with bounce-bake's defaults drawn in `--mode indirect`.
//
// Error (luminance Y, over the mask): mean |Y_r − Y_t|/Y_t (the reference's noise adds at most
// `ref_noise_allowance` to it) and the relative MSE mean((Y_r − Y_t)/Y_t)², whose expected
// reference share is `ref_rel_var` = mean(σ²/Y_t²) (σ ≤ Σ_c w_c σ_c: an upper bound), so
// rel_mse − ref_rel_var estimates the renderer's own part.
// Frame time: after two warm-up frames (the driver's shader JIT; the static scene's VPL shadow
// cubes are drawn once then), the median wall time of `--frames` frames of render + glFinish,
// and the mean process CPU time per frame (all llvmpipe threads), the steadier figure on a
// shared machine.
//
//   build/release/bin/bench_vpl_error --ref out/vpl_error_ref128.exr --out
//   docs/charts/vpl_error_vs_time.csv
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "frame_time.h"
#include "generated_vpl_bake.h"
#include "gl/context.h"
#include "gl/render_target.h"
#include "image/image_io.h"
#include "image/luminance.h"
#include "indirect_accuracy.h"
#include "indirect_reference.h"
#include "io/atomic_file.h"
#include "scene/load.h"

namespace fs = std::filesystem;
using namespace bounce;

namespace {

// Relative MSE over the comparison's mask, and the reference's expected share of it.
struct SquaredError {
  double relMse = 0.0;
  double refRelVar = 0.0;
};

SquaredError squaredError(const test::IndirectComparison& c, const Image& rendered,
                          const test::Reference& reference) {
  SquaredError e;
  for (std::size_t i = 0; i < c.mask.keep.size(); ++i) {
    if (!c.mask.keep[i]) continue;
    const double yt = luminance(reference.radiance.pixels[i]);
    const double d = (luminance(rendered.pixels[i]) - yt) / yt;
    const glm::vec3 s = reference.stdError.pixels[i];
    const double sigma = luminance(glm::dvec3(s)) / yt;
    e.relMse += d * d;
    e.refRelVar += sigma * sigma;
  }
  if (c.pixels > 0) {
    e.relMse /= static_cast<double>(c.pixels);
    e.refRelVar /= static_cast<double>(c.pixels);
  }
  return e;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scenePath = std::string(BOUNCE_SOURCE_DIR) + "/content/cornell_box/cornell_box.gltf";
  std::vector<int> caps = {64, 256, 1024, 4096, 16384};
  int size = 128, refSpp = 2048, frames = 5;
  uint32_t seed = 0;
  SceneBakeSettings lightmap = test::lightmapOnlySettings();  // bounce-bake's defaults
  lightmap.texelBudget = 16384;
  bool noLightmap = false;
  std::string refFile, outFile, imageDir;
  CLI::App app{
      "VPL error against frame time (culling × shadows × count) and the lightmap's point."};
  app.add_option("scene", scenePath, "scene (default: the Cornell box)");
  app.add_option("--caps", caps, "VPL caps (counts)")->delimiter(',');
  app.add_option("--seed", seed, "VPL generator seed");
  app.add_option("--size", size, "frame width = height, pixels");
  app.add_option("--ref-spp", refSpp, "reference samples per pixel");
  app.add_option("--ref", refFile,
                 "reference EXR: read if present (with <name>.se.exr), else traced and written");
  app.add_option("--frames", frames, "timed frames per configuration (median)")
      ->check(CLI::PositiveNumber);
  app.add_option("--texel-budget", lightmap.texelBudget, "lightmap atlas texel budget");
  app.add_option("--spp", lightmap.maxSpp, "lightmap: most samples per texel");
  app.add_flag("--no-lightmap", noLightmap, "skip the lightmap's point");
  app.add_option("--out", outFile, "CSV file (default: stdout)");
  app.add_option("--image-dir", imageDir, "write each frame as EXR here");
  CLI11_PARSE(app, argc, argv);
  try {
    const Scene scene = loadScene(scenePath);
    const Camera& camera = scene.cameras.at(0);
    const test::Reference reference =
        test::cachedIndirectReference(scene, camera, size, refSpp, refFile, "bench_vpl_error");
    const auto context = gl::createOSMesaContext();
    gl::RenderTarget target(size, size);
    std::ostringstream csv;
    csv << "method,vpls,culling,shadows,wall_ms,cpu_ms,mean_abs_rel_error,bias,rel_mse,"
           "ref_rel_var,ref_noise_allowance,pixels\n";
    auto measure = [&](const std::string& method, std::size_t vpls, int culling, int shadows,
                       ForwardRenderer& renderer) {
      const Image rendered = renderer.renderImage(camera, size, size);
      const test::IndirectComparison c = test::compareIndirect(scene, camera, rendered, reference);
      const SquaredError e = squaredError(c, rendered, reference);
      const test::FrameTime t = test::frameMilliseconds(renderer, camera, target, frames);
      char line[256];
      std::snprintf(line, sizeof line, "%s,%zu,%d,%d,%.2f,%.2f,%.4f,%+.4f,%.5f,%.5f,%.4f,%zu\n",
                    method.c_str(), vpls, culling, shadows, t.wallMs, t.cpuMs, c.meanAbsRelError,
                    c.bias, e.relMse, e.refRelVar, c.referenceNoise, c.pixels);
      csv << line;
      std::fprintf(stderr, "%s", line);
      if (!imageDir.empty()) {
        std::string name = method;
        if (method == "vpl")
          name += "_" + std::to_string(vpls) + "_c" + std::to_string(culling) + "s" +
                  std::to_string(shadows);
        writeExr(fs::path(imageDir) / (name + ".exr"), rendered);
      }
    };
    for (const int cap : caps) {
      const Bake bake = test::generatedVplBake(scene, cap, seed);
      for (const int culling : {0, 1})
        for (const int shadows : {0, 1}) {
          RendererSettings settings;
          settings.mode = RenderMode::Vpl;
          settings.vpls.culling = culling != 0;
          settings.vpls.shadows.enabled = shadows != 0;
          ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, &bake);
          measure("vpl", bake.vpls->size(), culling, shadows, renderer);
        }
    }
    if (!noLightmap) {
      std::fprintf(stderr, "bench_vpl_error: baking the lightmap (%d texels, <= %d spp)\n",
                   lightmap.texelBudget, lightmap.maxSpp);
      const Bake baked = bakeScene(scene, lightmap).folder;
      RendererSettings settings;
      settings.mode = RenderMode::Indirect;
      ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, &baked);
      measure("lightmap", 0, 0, 0, renderer);
    }
    if (outFile.empty())
      std::fputs(csv.str().c_str(), stdout);
    else {
      const std::string text = csv.str();
      writeFileAtomically(
          outFile, std::span(reinterpret_cast<const unsigned char*>(text.data()), text.size()));
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_vpl_error: error: %s\n", e.what());
    return 1;
  }
}
