// Shadow maps of spot and point lights: frame time against map resolution and filter, and the
// visibility error each setting leaves, in one run on one machine (offscreen, OSMesa).
//
//   bench_shadows [--out FILE.csv] [--width W] [--height H] [--frames N]
//                 [--resolutions 512,1024,2048,4096] [--lights spot,point]
//
// Scene: tests/render/shadow_scenes.h's occluderScene (3 m floor, box, post, 2 cm wall, tilted
// plate) with one light, seen by occluderCamera. Per (light, resolution, filter):
//   ms_per_frame     median over N frames of render + glFinish (no readback), after 2 warm-ups,
//                    wall clock;
//   cpu_ms_per_frame the same frames' process CPU time (all llvmpipe threads) per frame: the
//                    steadier figure on a shared machine, ≈ wall × threads on an idle one;
//   disagree_*       pixels where the map's visibility differs from ray-traced visibility by
//                    more than ½, outside a one-pixel band along true shadow edges (the test
//                    ShadowVisibility.* measure, at this frame size).
// CSV columns (one header line; the chart in docs/ reads them by name):
//   light,resolution,filter,filter_radius_texels,width,height,frames,ms_per_frame,
//   ms_per_frame_unshadowed,disagreeing_pixels,considered_pixels,disagree_fraction,is_default,
//   cpu_ms_per_frame,cpu_ms_per_frame_unshadowed
// is_default = 1 on the row of the renderer's own choice for this scene (resolution chosen per
// light, Poisson r = 1.5), measured first.
// filter is "hardware" (one 2×2 comparison tap) or "poisson" (16 rotated taps of that radius).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "frame_time.h"
#include "render/shadow_map_geometry.h"
#include "scene/framing.h"
#include "shadow_scenes.h"

namespace bounce::test {
namespace {

struct Options {
  std::string out = "bench_shadows.csv";
  int width = 1280, height = 720, frames = 10;
  std::vector<int> resolutions = {512, 1024, 2048, 4096};
  std::vector<std::string> lights = {"spot", "point"};
};

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, ',');) parts.push_back(part);
  return parts;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) {
      std::fprintf(stderr, "bench_shadows: %s needs a value\n", flag.c_str());
      std::exit(2);
    }
    const std::string value = argv[++i];
    if (flag == "--out") {
      o.out = value;
    } else if (flag == "--width") {
      o.width = std::stoi(value);
    } else if (flag == "--height") {
      o.height = std::stoi(value);
    } else if (flag == "--frames") {
      o.frames = std::max(1, std::stoi(value));
    } else if (flag == "--resolutions") {
      o.resolutions.clear();
      for (const std::string& r : split(value)) o.resolutions.push_back(std::stoi(r));
    } else if (flag == "--lights") {
      o.lights = split(value);
    } else {
      std::fprintf(stderr, "bench_shadows: unknown flag %s\n", flag.c_str());
      std::exit(2);
    }
  }
  return o;
}

struct FilterCase {
  const char* name;
  ShadowFilter filter;
  float radius;
};

int run(const Options& o) {
  testContext();
  const Camera camera = occluderCamera();
  gl::RenderTarget target(o.width, o.height);
  const std::string temporary = o.out + ".partial";
  std::ofstream csv(temporary);
  csv << "light,resolution,filter,filter_radius_texels,width,height,frames,ms_per_frame,"
         "ms_per_frame_unshadowed,disagreeing_pixels,considered_pixels,disagree_fraction,"
         "is_default,cpu_ms_per_frame,cpu_ms_per_frame_unshadowed\n";
  const FilterCase filters[] = {{"hardware", ShadowFilter::Hardware, 0.0f},
                                {"poisson", ShadowFilter::Poisson, 1.5f},
                                {"poisson", ShadowFilter::Poisson, 3.0f}};
  for (const std::string& kind : o.lights) {
    const Scene scene = occluderScene(kind == "point" ? occluderPoint() : occluderSpot());
    RendererSettings unshadowed;
    unshadowed.shadows.enabled = false;
    ForwardRenderer plain(scene, gl::shaderDirectory(), unshadowed);
    const FrameTime plainMs = frameMilliseconds(plain, camera, target, o.frames);
    const Image without = plain.renderImage(camera, o.width, o.height);
    const Bounds bounds = sceneBounds(scene);
    Box sceneBox;
    sceneBox.grow(bounds.lo);
    sceneBox.grow(bounds.hi);
    const Light& light = scene.lights[0];
    const int chosen = light.type == LightType::Spot
                           ? spotShadowViewFor(light, sceneBox, ShadowSettings{}).resolution
                           : pointShadowResolutionFor(light.position, sceneBox, ShadowSettings{});
    std::vector<int> resolutions = {0};
    resolutions.insert(resolutions.end(), o.resolutions.begin(), o.resolutions.end());
    for (const int resolution : resolutions) {
      for (const FilterCase& f : filters) {
        if (resolution == 0 && f.radius != ShadowSettings{}.filterRadius) continue;
        RendererSettings settings;
        settings.shadows.resolution = resolution;
        settings.shadows.filter = f.filter;
        settings.shadows.filterRadius = f.radius;
        ForwardRenderer renderer(scene, gl::shaderDirectory(), settings);
        const FrameTime ms = frameMilliseconds(renderer, camera, target, o.frames);
        const Agreement a = compareVisibility(
            scene, camera, renderer.renderImage(camera, o.width, o.height), without);
        char line[256];
        std::snprintf(line, sizeof line,
                      "%s,%d,%s,%.2f,%d,%d,%d,%.3f,%.3f,%d,%d,%.6f,%d,%.3f,%.3f\n", kind.c_str(),
                      resolution == 0 ? chosen : resolution, f.name, f.radius, o.width, o.height,
                      o.frames, ms.wallMs, plainMs.wallMs, a.disagreeing, a.considered,
                      a.fraction(), resolution == 0 ? 1 : 0, ms.cpuMs, plainMs.cpuMs);
        csv << line;
        std::fprintf(stderr, "bench_shadows: %s", line);
      }
    }
  }
  csv.close();
  if (!csv) {
    std::fprintf(stderr, "bench_shadows: cannot write %s\n", temporary.c_str());
    return 1;
  }
  std::filesystem::rename(temporary, o.out);
  std::fprintf(stderr, "bench_shadows: wrote %s\n", o.out.c_str());
  return 0;
}

}  // namespace
}  // namespace bounce::test

int main(int argc, char** argv) {
  try {
    return bounce::test::run(bounce::test::parse(argc, argv));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_shadows: error: %s\n", e.what());
    return 1;
  }
}
