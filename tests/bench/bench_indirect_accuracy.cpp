// The full-size measurement of the baked light's accuracy (docs/renderer.md, "Baked light"): bake a
// scene in-process with bounce-bake's settings, draw the renderer's indirect-only frame (or, with
// --frame full, the whole frame), and compare it with bounce-trace --indirect-only (or the full
// trace) over the static, non-emissive, edge-free pixels (tests/render/indirect_accuracy.h);
// with --box K the frame is drawn at K× the resolution and box-filtered, as the tracer averages
// each pixel's area. The reference is cached as EXR (radiance + standard
// error) so a sweep of bake settings traces it once. Prints one CSV line per run:
//   texel_budget,texel_size_m,atlas_w,atlas_h,spp_cap,target_error,denoise,bake_s,
//   est_error_mean,mean_abs_rel_error,bias,ref_rel_std_error,ref_noise_allowance,pixels
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <string>

#include "bake_folder/gather.h"
#include "gl/context.h"
#include "image/image_io.h"
#include "indirect_accuracy.h"
#include "indirect_reference.h"
#include "scene/load.h"

namespace fs = std::filesystem;
using namespace bounce;

int main(int argc, char** argv) {
  std::string scenePath = std::string(BOUNCE_SOURCE_DIR) + "/content/cornell_box/cornell_box.gltf";
  SceneBakeSettings bake = test::lightmapOnlySettings();
  std::string denoise = "on";
  int size = 128, height = 0, refSpp = 4096, box = 1;
  std::string refFile, outDir, cameraName, frame = "indirect";
  bool header = false;
  CLI::App app{"Renderer's indirect frame (with a fresh bake) against the path tracer."};
  app.add_option("scene", scenePath, "scene (default: the Cornell box)");
  app.add_option("--texel-budget", bake.texelBudget,
                 "atlas texel budget (default 0: bounce-bake's texel rule)");
  app.add_option("--texel-size", bake.texelSize, "texel edge in metres (overrides the budget)");
  app.add_option("--spp", bake.maxSpp, "most samples per texel");
  app.add_option("--target-error", bake.targetError, "per-texel relative error target");
  app.add_option("--vpls", bake.vpls,
                 "most VPLs (default 0: the lightmap alone; a static instance the atlas leaves to "
                 "the VPLs then reads no indirect light)");
  app.add_option("--denoise", denoise, "on|off")->check(CLI::IsMember({"on", "off"}));
  std::string gather = gatherName(bake.gather);
  app.add_option("--gather", gather, "paths|cache (bounce-bake --gather)")
      ->check(CLI::IsMember({"paths", "cache"}));
  app.add_option("--cache-spp", bake.cacheSpp, "samples per texel of the cache pass");
  app.add_option("--error-floor", bake.errorFloor,
                 "fraction of the cache's mean irradiance below which a texel stops at an "
                 "absolute error (bounce-bake --error-floor)");
  app.add_option("--size", size, "frame width (and height unless --height), pixels");
  app.add_option("--height", height, "frame height, pixels (default: --size)");
  app.add_option("--camera", cameraName, "camera name (default: the scene's first)");
  app.add_option("--box", box, "draw at K times the resolution and box-filter (default 1)")
      ->check(CLI::Range(1, 16));
  app.add_option("--frame", frame, "indirect|full: the renderer's mode and the tracer's paths")
      ->check(CLI::IsMember({"indirect", "full"}));
  app.add_option("--ref-spp", refSpp, "reference samples per pixel");
  app.add_option("--ref", refFile,
                 "reference EXR: read if present (with <name>.se.exr), else written");
  app.add_option("--out-dir", outDir, "write <frame>.exr/.png, reference.png and mask.png here");
  app.add_flag("--header", header, "print the CSV header first");
  CLI11_PARSE(app, argc, argv);
  bake.denoise = denoise == "on";
  bake.gather = *parseGather(gather);  // checked by CLI11
  try {
    const Scene scene = loadScene(scenePath);
    if (height == 0) height = size;
    const Camera& camera = scene.cameras.at(cameraName.empty() ? 0 : scene.findCamera(cameraName));
    const bool full = frame == "full";
    const test::Reference reference = test::cachedReference(
        scene, camera, size, height, refSpp, full ? PathSet::All : PathSet::IndirectOnly, refFile,
        "bench_indirect_accuracy");
    const Bake baked = bakeScene(scene, bake).folder;
    const auto context = gl::createOSMesaContext();
    RendererSettings settings;
    settings.mode = full ? RenderMode::Full : RenderMode::Indirect;
    ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, &baked);
    const Image rendered = test::renderAreaAveraged(renderer, camera, size, height, box);
    const test::IndirectComparison c = test::compareIndirect(scene, camera, rendered, reference);
    if (!outDir.empty()) {
      writeExr(fs::path(outDir) / (frame + ".exr"), rendered);
      writePng(fs::path(outDir) / (frame + ".png"), rendered, 0.0f);
      writePng(fs::path(outDir) / "reference.png", reference.radiance, 0.0f);
      Image mask(size, height);
      for (std::size_t i = 0; i < mask.pixels.size(); ++i)
        mask.pixels[i] = glm::vec3(c.mask.keep[i] ? 1.0f : 0.0f);
      writeDisplayPng(fs::path(outDir) / "mask.png", mask);
    }
    if (header)
      std::printf(
          "texel_budget,texel_size_m,atlas_w,atlas_h,spp_cap,target_error,denoise,bake_s,"
          "est_error_mean,mean_abs_rel_error,bias,ref_rel_std_error,ref_noise_allowance,"
          "pixels\n");
    std::printf("%d,%.5f,%d,%d,%d,%.3f,%s,%.3f,%.4f,%.4f,%+.4f,%.4f,%.4f,%zu\n", bake.texelBudget,
                baked.layout.texelSize, baked.layout.width, baked.layout.height, bake.maxSpp,
                bake.targetError, denoise.c_str(), baked.manifest.measured.seconds.total,
                baked.manifest.estimatedError.mean, c.meanAbsRelError, c.bias, c.meanRelStdError,
                c.referenceNoise, c.pixels);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_indirect_accuracy: error: %s\n", e.what());
    return 1;
  }
}
