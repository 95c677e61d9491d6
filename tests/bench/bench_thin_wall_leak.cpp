// How much light crosses a wall thinner than a texel (docs/real_scenes.md, "Light through thin
// walls"): a lit and a dark room, each 2 m × 2 m × 2.5 m, share ONE floor quad, ONE ceiling quad
// and two side-wall quads that run through a dividing wall (a box t thick), as slabs and walls
// of real levels do. A 10 W/sr point light hangs in the lit room; nothing can reach the dark
// room but through the wall, so every pixel of it is exactly 0 in the path tracer. For each wall
// thickness and texel size (the surfaces cut where the wall crosses them, as loadScene does;
// --uncut: not, as before the cut): a default bake (bakeScene, the texels asked), then the
// renderer's full and indirect frames from a camera in the dark room facing the wall, and the lit
// room's mean luminance from the mirror camera. Prints one CSV line per case: the dark room's
// largest pixel and its 99th percentile, as fractions of the lit room's mean (goal: every pixel
// under 1%).
//
//   bench_thin_wall_leak [--thickness M,...] [--texel-size M,...] [--size PIXELS] [--spp N]
//                        [--image-dir DIR]   (each case's dark-room frames, 4 EV brighter)
//                        [--uncut]           (no cuts where the wall crosses the surfaces)
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "gl/context.h"
#include "image/image_io.h"
#include "image/luminance.h"
#include "indirect_accuracy.h"
#include "shadow_scenes.h"
#include "test_scenes.h"
#include "thin_wall_scene.h"

namespace {

using namespace bounce;

struct Leak {
  double largest = 0.0, p99 = 0.0;  // of the dark room's pixels, / the lit room's mean
};

Leak darkRoomLeak(const Image& dark, double litMean) {
  std::vector<double> y(dark.pixels.size(), 0.0);
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = luminance(dark.pixels[i]) / litMean;
  if (y.empty()) return {};
  std::sort(y.begin(), y.end());
  return {y[y.size() - 1], y[static_cast<std::size_t>(0.99 * static_cast<double>(y.size() - 1))]};
}

double meanLuminance(const Image& image) {
  double sum = 0.0;
  for (const glm::vec3& p : image.pixels) sum += luminance(p);
  return sum / static_cast<double>(image.pixels.size());
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<float> thicknesses = {0.005f, 0.02f, 0.05f}, texels = {0.025f, 0.05f, 0.1f};
  int size = 96, spp = 1024;
  std::string imageDir;
  bool uncut = false;
  CLI::App app{"Light that crosses a wall thinner than a texel, into a dark room."};
  app.add_option("--thickness", thicknesses, "dividing wall thicknesses, m")->delimiter(',');
  app.add_option("--texel-size", texels, "lightmap texel sizes, m")->delimiter(',');
  app.add_option("--size", size, "frame width = height, pixels");
  app.add_option("--spp", spp, "most samples per texel");
  app.add_option("--image-dir", imageDir, "write the dark room's full and indirect frames here");
  app.add_flag("--uncut", uncut, "bake the surfaces as written, not cut at the wall");
  CLI11_PARSE(app, argc, argv);
  try {
    const auto context = gl::createOSMesaContext();
    // The cameras stand 1.8 m from the wall at 1.2 m and look at its foot, seeing the floor, the
    // ceiling and both side walls where they pass through it.
    const Camera dark = test::lookingAt({1.9f, 1.2f, 0.0f}, {0.0f, 0.8f, 0.0f}, 1.4f);
    const Camera lit = test::lookingAt({-1.9f, 1.2f, 0.0f}, {0.0f, 0.8f, 0.0f}, 1.4f);
    std::printf(
        "thickness_m,texel_m,bake_s,full_largest,full_p99,indirect_largest,indirect_p99,"
        "lit_mean\n");
    for (const float t : thicknesses)
      for (const float texel : texels) {
        const Scene scene = uncut ? test::thinWallRoomsAsWritten(t) : test::thinWallRooms(t);
        SceneBakeSettings settings = test::lightmapOnlySettings();
        settings.texelSize = texel;
        settings.maxSpp = spp;
        const Bake bake = bakeScene(scene, settings).folder;
        RendererSettings full;
        full.mode = RenderMode::Full;
        ForwardRenderer renderer(scene, gl::shaderDirectory(), full, &bake);
        const double litMean = meanLuminance(renderer.renderImage(lit, size, size, 4));
        const Image darkFull = renderer.renderImage(dark, size, size, 4);
        // Both frames with 4 samples a pixel, as bounce-render draws them: a lookup at an edge
        // fragment of a partly covered pixel is where a chart's neighbour can show.
        RendererSettings indirect;
        indirect.mode = RenderMode::Indirect;
        ForwardRenderer indirectRenderer(scene, gl::shaderDirectory(), indirect, &bake);
        const Image darkIndirect = indirectRenderer.renderImage(dark, size, size, 4);
        const Leak f = darkRoomLeak(darkFull, litMean), i = darkRoomLeak(darkIndirect, litMean);
        if (!imageDir.empty()) {
          char name[64];
          std::snprintf(name, sizeof name, "wall%.3f_texel%.3f", static_cast<double>(t),
                        static_cast<double>(texel));
          writePng(std::filesystem::path(imageDir) / (std::string(name) + "_full.png"), darkFull,
                   4.0f);
          writePng(std::filesystem::path(imageDir) / (std::string(name) + "_indirect.png"),
                   darkIndirect, 4.0f);
        }
        std::printf("%.3f,%.3f,%.1f,%.4f,%.4f,%.4f,%.4f,%.4f\n", static_cast<double>(t),
                    static_cast<double>(texel), bake.manifest.measured.seconds.total, f.largest,
                    f.p99, i.largest, i.p99, litMean);
        std::fflush(stdout);
      }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_thin_wall_leak: error: %s\n", e.what());
    return 1;
  }
}
